// The thesis's test images and densities (Tables 3.5 and 3.6) for tests that run the methods on
// them: bull at 0.125-1 %, lena and peppers at 0.5-3 %, read from $ERD_IMAGES (default
// ../shared/images). An image that cannot be read is skipped with a warning. Under the
// sanitizers (ERD_SANITIZED set, ~20x slower) the lowest density of each image stands for all.
#pragma once
#include <catch2/catch.hpp>

#include <cstdlib>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/methods/methods.h"
#include "cli/fileio.h"
#include "cli/image_io.h"

namespace erd::test {

// Runs each of the named methods (the registry's names) on every case and calls
// run(image, result) with its result, after checking that it made exactly the requested count.
template <class Run>
void for_each_thesis_case(std::initializer_list<const char*> method_names, Run run) {
    const char* dir = std::getenv("ERD_IMAGES");
    const std::string images = dir && *dir ? dir : "../shared/images";
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;
    const std::vector<std::pair<const char*, std::vector<double>>> cases = {
        {"bull", {0.125, 0.25, 0.5, 1}}, {"lena", {0.5, 1, 2, 3}}, {"peppers", {0.5, 1, 2, 3}}};
    for (const auto& c : cases) {
        std::string bytes;
        Image im;
        if (!cli::read_file(images + "/" + c.first + ".pgm", &bytes).ok() ||
            !cli::decode_pgm(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &im, nullptr).ok()) {
            WARN("skipped: " << images << "/" << c.first << ".pgm not readable");
            continue;
        }
        for (const double d : c.second) {
            if (sanitized && d != c.second.front()) continue;
            GenerateOptions o;
            o.density = d;
            o.density_given = true;
            INFO(c.first << " " << d << "%");
            for (const char* name : method_names) {
                INFO(name);
                const MethodInfo* m = find_method(name);
                REQUIRE(m != nullptr);
                GenerateResult r;
                REQUIRE(m->run(im, o, &r).ok());
                CHECK(r.achieved == r.requested);
                run(im, r);
            }
        }
    }
}

}  // namespace erd::test
