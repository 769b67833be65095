// The thesis's test images and densities (Tables 3.5 and 3.6) for tests that run the methods on
// them: bull at 0.125-1 %, lena and peppers at 0.5-3 %, read from $ERD_IMAGES (default
// ../shared/images). A missing image fails the test unless ERD_ALLOW_SKIP=1 (tests/erd_run.h).
// Under the sanitizers (ERD_SANITIZED set, ~20x slower) the lowest density of each image stands
// for all.
#pragma once
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "algorithms/methods/methods.h"
#include "cli/fileio.h"
#include "cli/image_io.h"
#include "tests/erd_run.h"

namespace erd::test {

struct ThesisCase {
    const char* image;  // bull, lena, peppers
    double density;     // percent
};

// The image x density matrix, for GENERATE.
inline std::vector<ThesisCase> thesis_cases() {
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;
    const std::vector<ThesisCase> all = {{"bull", 0.125}, {"bull", 0.25},  {"bull", 0.5},    {"bull", 1},
                                         {"lena", 0.5},   {"lena", 1},     {"lena", 2},      {"lena", 3},
                                         {"peppers", 0.5}, {"peppers", 1}, {"peppers", 2},   {"peppers", 3}};
    std::vector<ThesisCase> out;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (!sanitized || i == 0 || std::string(all[i].image) != all[i - 1].image) out.push_back(all[i]);
    return out;
}

// Reads $ERD_IMAGES/NAME.pgm; false (a failed check, or a warning under ERD_ALLOW_SKIP=1) when it
// cannot be read.
inline bool read_thesis_image(const std::string& name, Image* im) {
    const char* dir = std::getenv("ERD_IMAGES");
    const std::string path = std::string(dir && *dir ? dir : "../shared/images") + "/" + name + ".pgm";
    std::string bytes;
    const bool ok = cli::read_file(path, &bytes).ok() &&
                    cli::decode_pnm(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), im, nullptr).ok();
    return erd_test::have_input(ok, path + " not readable (set ERD_IMAGES)");
}

// One run of the test case per method x image x density (Catch GENERATE): runs the named method
// (the registry's names) on the case, checks that it made exactly the requested count, and calls
// run(image, result).
template <class Run>
void for_each_thesis_case(std::vector<const char*> method_names, Run run) {
    const ThesisCase c = GENERATE(from_range(thesis_cases()));
    const char* name = GENERATE_COPY(from_range(method_names));
    Image im;
    if (!read_thesis_image(c.image, &im)) return;
    INFO(c.image << " " << c.density << "% " << name);
    GenerateOptions o;
    o.density = c.density;
    o.density_given = true;
    const MethodInfo* m = find_method(name);
    REQUIRE(m != nullptr);
    GenerateResult r;
    REQUIRE(m->run(im, o, &r).ok());
    CHECK(r.achieved == r.requested);
    run(im, r);
}

}  // namespace erd::test
