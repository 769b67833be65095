// The Catch2 main (Debian package catch2, header only).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
