// The kernel tests' Catch2 check of a Cdt (tests/cdt_util.h holds what the fuzz targets share too).
#pragma once

#include <catch2/catch.hpp>

#include <string>

#include "kernel/cdt.h"

// verify() passes; its reason shown when it does not.
inline void must_verify(const erd::Cdt& cdt) {
    std::string why;
    const bool ok = cdt.verify(&why);
    INFO(why);
    REQUIRE(ok);
}
