// Packaging: the thesis's seven command names (run through symlinks named as the thesis has
// them, compared with the erd subcommands) and the public API (api/erd.h): validation, exit
// modes, the kernel (two calls on two threads: test_row_parallel.cpp). Installing it: test_install.cpp.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>
#include <sstream>
#include <vector>

#include "api/erd.h"
#include "algorithms/methods/methods.h"
#include "algorithms/model/metrics.h"
#include "algorithms/imaging/synth.h"
#include "cli/image_io.h"
#include "tests/erd_run.h"
#include "tests/synth_util.h"

using namespace erd_test;

namespace {

// A folder holding bin/<alias> -> $ERD_BIN for all seven names and bin/erd, plus a small
// synthetic image in plain PGM ("plain pnm", as the thesis's programs read) and raw PGM.
struct AliasDir {
    TempDir dir;
    std::string erd;
    AliasDir(int w = 48, int h = 40) {
        erd = absolute(erd_bin());
        std::string bin = dir.file("bin");
        ::mkdir(bin.c_str(), 0755);
        for (const char* a : kAliases) REQUIRE(::symlink(erd.c_str(), (bin + "/" + a).c_str()) == 0);
        REQUIRE(::symlink(erd.c_str(), (bin + "/erd").c_str()) == 0);
        const erd::Image im = synth_image(w, h);
        spit(dir.file("img.pnm"), erd::cli::encode_pnm(im, true));
        spit(dir.file("img.pgm"), erd::cli::encode_pnm(im, false));
    }
    RunResult run(const std::string& cmd) const { return run_in(dir.path, "PATH=" + sh_quote(dir.file("bin")) + ":\"$PATH\" " + cmd); }
    std::string read(const std::string& name) const { return slurp(dir.file(name)); }
};

bool same_model(const erd::Model& a, const erd::Model& b) {
    return a.kind == b.kind && a.width == b.width && a.height == b.height && a.vertices == b.vertices &&
           a.values == b.values && a.faces == b.faces && a.corner_values == b.corner_values &&
           a.constraints == b.constraints;
}

}  // namespace

TEST_CASE("ywb, gpi, erd_ed, erd_gpi write the bytes erd generate writes", "[packaging]") {
    // erd_ed and erd_gpi run the thesis's method: erd generate --thesis (lead, 02:37).
    if (!need_binary()) return;
    AliasDir d;
    struct Case { const char* alias; const char* thesis_args; const char* erd_args; const char* ext; };
    const Case cases[] = {
        // The thesis's own examples (A.5.1), on the small image.
        {"ywb", "-i img.pnm -d 3", "--method ed -i img.pnm -d 3", "model"},
        {"gpi", "-i img.pnm -d 1", "--method gpi -i img.pnm -d 1", "model"},
        {"erd_ed", "-i img.pnm -d 4 -l 3 -b 0.17 -r 0.4", "--method erded --thesis -i img.pnm -d 4 -l 3 -b 0.17 -r 0.4", "erd"},
        {"erd_gpi", "-i img.pnm -d 3 -l 5 -e 1 -b 0.4", "--method erdgpi --thesis -i img.pnm -d 3 -l 5 -e 1 -b 0.4", "erd"},
        // -n, and -d winning over -n ("$num is ignored"); binary PGM input; defaults (3%).
        {"gpi", "-i img.pgm -n 60", "--method gpi -i img.pgm -n 60", "model"},
        {"ywb", "-i img.pnm -n 5 -d 2", "--method ed -i img.pnm -d 2", "model"},
        {"erd_gpi", "-i img.pnm", "--method erdgpi --thesis -i img.pnm", "erd"},
        {"erd_ed", "-iimg.pnm -d2 -f 1 -w 1 -s 5 -B 0 -x 1", "--method erded --thesis -i img.pnm -d 2 -f 1 -w 1 -s 5 -B 0 -x 1", "erd"},
        // The thesis's "1, otherwise ..." flags: -w 7 is the fixed-distance rule, -S 5 non-simple.
        {"erd_gpi", "-i img.pnm -d 2 -w 7 -S 5", "--method erdgpi --thesis -i img.pnm -d 2 -w 0 -S 1", "erd"},
    };
    for (const auto& c : cases) {
        INFO(c.alias << " " << c.thesis_args);
        std::string ext = c.ext;
        RunResult a = d.run(std::string(c.alias) + " " + c.thesis_args + " -o a." + ext + " -t a.tri -p a.pl");
        RunResult b = d.run(std::string("erd generate ") + c.erd_args + " -o b." + ext + " -t b.tri -p b.pl");
        INFO(a.err);
        REQUIRE(a.status == 0);
        REQUIRE(b.status == 0);
        CHECK(!d.read("a." + ext).empty());
        CHECK(d.read("a." + ext) == d.read("b." + ext));
        CHECK(d.read("a.tri") == d.read("b.tri"));
        CHECK(d.read("a.pl") == d.read("b.pl"));
        CHECK(a.out == b.out);
    }
    // The kind of model follows the method: .model files start with maxval then NV; an .erd has
    // wedge lines after its faces. Both read back as the kind the thesis names.
    d.run("ywb -i img.pnm -d 3 -o lena.model");
    d.run("erd_gpi -i img.pnm -d 3 -o lena.erd");
    CHECK(!d.read("lena.model").empty());
    CHECK(!d.read("lena.erd").empty());
}

TEST_CASE("imgsyn and imgsyn_aa: model on stdin, plain PGM on stdout, as erd reconstruct", "[packaging]") {
    if (!need_binary()) return;
    AliasDir d;
    REQUIRE(d.run("ywb -i img.pnm -d 3 -o lena.model").status == 0);
    REQUIRE(d.run("erd_gpi -i img.pnm -d 3 -o lena.erd").status == 0);

    RunResult s = d.run("imgsyn < lena.model > lena_reconstructed_model.pnm");
    INFO(s.err);
    REQUIRE(s.status == 0);
    REQUIRE(d.run("erd reconstruct lena.model -o ref_model.pgm --no-aa --plain").status == 0);
    std::string got = d.read("lena_reconstructed_model.pnm");
    CHECK(got.compare(0, 2, "P2") == 0);
    CHECK(got == d.read("ref_model.pgm"));

    RunResult aa = d.run("imgsyn_aa < lena.erd > lena_reconstructed_erd.pnm");
    INFO(aa.err);
    REQUIRE(aa.status == 0);
    REQUIRE(d.run("erd reconstruct lena.erd -o ref_erd.pgm --plain").status == 0);
    got = d.read("lena_reconstructed_erd.pnm");
    CHECK(got.compare(0, 2, "P2") == 0);
    CHECK(got == d.read("ref_erd.pgm"));

    // The reconstruction has the image's size and maxval, and every vertex of the basic model
    // gets its sample back (point evaluation).
    erd::Image orig, rec;
    std::string warn;
    REQUIRE(erd::cli::read_image(d.dir.file("img.pnm"), &orig, &warn));
    REQUIRE(erd::cli::read_image(d.dir.file("lena_reconstructed_model.pnm"), &rec, &warn));
    CHECK(rec.width == orig.width);
    CHECK(rec.height == orig.height);
    CHECK(rec.maxval == orig.maxval);
    CHECK(rec.at(0, 0) == orig.at(0, 0));
    CHECK(rec.at(orig.width - 1, orig.height - 1) == orig.at(orig.width - 1, orig.height - 1));

    // Neither takes arguments.
    RunResult bad = d.run("imgsyn lena.model");
    CHECK(bad.status == 2);
    CHECK_THAT(bad.err, Catch::Contains("usage: imgsyn"));
}

TEST_CASE("Cal_PSNR prints what erd psnr prints", "[packaging]") {
    if (!need_binary()) return;
    AliasDir d;
    REQUIRE(d.run("erd_gpi -i img.pnm -d 3 -o m.erd").status == 0);
    REQUIRE(d.run("imgsyn_aa < m.erd > rec.pnm").status == 0);
    RunResult a = d.run("Cal_PSNR img.pnm rec.pnm");
    RunResult b = d.run("erd psnr img.pnm rec.pnm");
    REQUIRE(a.status == 0);
    CHECK(a.out == b.out);
    erd::Image orig, rec;
    std::string warn;
    REQUIRE(erd::cli::read_image(d.dir.file("img.pnm"), &orig, &warn));
    REQUIRE(erd::cli::read_image(d.dir.file("rec.pnm"), &rec, &warn));
    double want = erd::psnr(orig, rec);
    REQUIRE(std::isfinite(want));
    CHECK(std::stod(a.out) == Approx(want).margin(5e-5));
    CHECK(d.run("Cal_PSNR img.pnm img.pgm").out == "inf\n");  // same samples, plain and raw

    RunResult one = d.run("Cal_PSNR img.pnm");
    CHECK(one.status == 2);
    CHECK_THAT(one.err, Catch::Contains("usage: Cal_PSNR"));
}

TEST_CASE("thesis exit modes -x 0/1/2 through gpi: exit 3 and the exact lines", "[packaging]") {
    if (!need_binary()) return;
    AliasDir d;
    // A constant image: greedy insertion has nothing to refine, so 20 points cannot be reached.
    erd::Image flat(16, 16, 255);
    for (auto& s : flat.samples) s = 100;
    spit(d.dir.file("flat.pnm"), erd::cli::encode_pnm(flat, true));

    RunResult m0 = d.run("gpi -i flat.pnm -n 20 -o m0.model");
    CHECK(m0.status == 3);
    CHECK_THAT(m0.err, Catch::Contains("ERROR: target sampling density not achieved exactly (requested 20 but got 4)"));
    RunResult m1 = d.run("gpi -i flat.pnm -n 20 -o m1.model -x 1");
    CHECK(m1.status == 0);
    CHECK_THAT(m1.err, Catch::Contains("WARNING: target sampling density not achieved exactly (requested 20 but got 4)"));
    CHECK(!d.read("m1.model").empty());
    RunResult m2 = d.run("gpi -i flat.pnm -n 20 -o m2.model -x 2");
    CHECK(m2.status == 0);
    CHECK(m2.err.find("target sampling density") == std::string::npos);
    CHECK(d.read("m1.model") == d.read("m2.model"));
}

TEST_CASE("thesis programs take exactly the thesis's flags", "[packaging]") {
    if (!need_binary()) return;
    AliasDir d;
    struct Bad { const char* cmd; const char* fragment; };
    const Bad bad[] = {
        {"ywb -i img.pnm -l 3", "ywb: unknown option -l"},            // an ERD flag
        {"gpi -i img.pnm -f 1", "gpi: unknown option -f"},
        {"erd_gpi -i img.pnm -B 1", "erd_gpi: unknown option -B"},    // ERDED only
        {"erd_gpi -i img.pnm -f 0", "erd_gpi: unknown option -f"},
        {"ywb --input img.pnm", "ywb: unknown option --input"},       // no long forms
        {"ywb -i img.pnm extra", "ywb: unexpected argument 'extra'"},
        {"erd_ed -i img.pnm -w yes", "erd_ed: -w needs an integer"},
        {"gpi -i", "gpi: option -i needs a value"},
        {"Cal_PSNR -v img.pnm", "usage: Cal_PSNR"},
    };
    for (const auto& b : bad) {
        INFO(b.cmd);
        RunResult r = d.run(b.cmd);
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::Contains(b.fragment));
    }
    // Values the erd subcommand rejects keep its message and status.
    RunResult r = d.run("ywb -i img.pnm -d abc -o x.model");
    CHECK(r.status == 2);
    CHECK(!exists(d.dir.file("x.model")));
    RunResult missing = d.run("ywb -i nosuch.pnm -o x.model");
    CHECK(missing.status == 2);
    CHECK_THAT(missing.err, Catch::Contains("nosuch.pnm"));
}

TEST_CASE("public API: generate, reconstruct, psnr agree with the CLI's library calls", "[packaging]") {
    erd::Image im = synth_image(64, 48, 8, 3);
    erd::api::Options opt;
    opt.generate.density = 2.0;
    opt.generate.density_given = true;
    erd::Model model;
    erd::api::GenerateInfo info;
    REQUIRE(erd::api::generate(erd::api::Method::erdgpi, erd::api::view_of(im), opt, &model, &info));
    CHECK(info.requested == std::size_t(std::lround(0.02 * 64 * 48)));
    CHECK(info.achieved == model.vertices.size());
    CHECK(model.kind == erd::ModelKind::erd);

    // The same as the registry entry the CLI runs.
    erd::GenerateResult direct;
    REQUIRE(erd::find_method("erdgpi")->run(im, opt.generate, &direct));
    CHECK(same_model(model, direct.model));

    erd::Image aa, pt;
    REQUIRE(erd::api::reconstruct(model, true, &aa));
    REQUIRE(erd::api::reconstruct(model, false, &pt));
    CHECK(aa.width == 64);
    CHECK(aa.height == 48);
    double db_aa = 0, db_pt = 0;
    REQUIRE(erd::api::psnr(erd::api::view_of(im), erd::api::view_of(aa), &db_aa));
    REQUIRE(erd::api::psnr(erd::api::view_of(im), erd::api::view_of(pt), &db_pt));
    CHECK(db_aa == erd::psnr(im, aa));
    CHECK(db_aa > 20.0);
    CHECK(db_pt > 20.0);

    // A strided view of the same samples (each row followed by 3 junk samples) gives the same mesh.
    std::vector<std::uint16_t> padded;
    for (int y = 0; y < im.height; ++y) {
        for (int x = 0; x < im.width; ++x) padded.push_back(im.at(x, y));
        for (int k = 0; k < 3; ++k) padded.push_back(65535);
    }
    erd::api::ImageView strided{im.width, im.height, im.maxval, padded.data(), std::size_t(im.width + 3)};
    erd::Model model2;
    REQUIRE(erd::api::generate(erd::api::Method::erdgpi, strided, opt, &model2));
    CHECK(same_model(model, model2));
}

TEST_CASE("public API: bad views, names, memory cap and exact modes give status values", "[packaging]") {
    erd::Image im = synth_image(32, 24, 8, 1);
    erd::api::Options opt;
    erd::Model model;
    erd::api::ImageView v = erd::api::view_of(im);

    erd::api::ImageView bad = v;
    bad.samples = nullptr;
    CHECK(erd::api::generate(erd::api::Method::gpi, bad, opt, &model).code == erd::Code::input);
    bad = v;
    bad.width = 0;
    CHECK(erd::api::generate(erd::api::Method::gpi, bad, opt, &model).code == erd::Code::input);
    bad = v;
    bad.maxval = 10;  // samples above it
    erd::Status st = erd::api::generate(erd::api::Method::gpi, bad, opt, &model);
    CHECK(st.code == erd::Code::input);
    CHECK_THAT(st.message, Catch::Contains("exceeds maxval 10"));
    bad = v;
    bad.stride = 5;
    CHECK(erd::api::generate(erd::api::Method::gpi, bad, opt, &model).code == erd::Code::input);
    CHECK(erd::api::generate(erd::api::Method::gpi, v, opt, nullptr).code == erd::Code::input);

    erd::api::Method m = erd::api::Method::ed;
    CHECK(erd::api::method_from_name("erdgpi", &m));
    CHECK(m == erd::api::Method::erdgpi);
    CHECK(erd::api::method_from_name("ywb", &m).code == erd::Code::input);
    for (auto k : {erd::api::Method::ed, erd::api::Method::gpi, erd::api::Method::erded, erd::api::Method::erdgpi}) {
        erd::api::Method back = erd::api::Method::ed;
        CHECK(erd::api::method_from_name(erd::api::method_name(k), &back));
        CHECK(back == k);
    }

    // The memory cap refuses before any work; a generous one lets the job run.
    erd::api::Options capped = opt;
    capped.max_memory = 1000;
    st = erd::api::generate(erd::api::Method::erdgpi, v, capped, &model);
    CHECK(st.code == erd::Code::runtime);
    CHECK_THAT(st.message, Catch::Contains("max_memory"));
    capped.max_memory = erd::api::memory_estimate(erd::api::Method::erdgpi, 32, 24, opt);
    CHECK(erd::api::generate(erd::api::Method::erdgpi, v, capped, &model));
    CHECK(erd::api::memory_estimate(erd::api::Method::erdgpi, 512, 512, opt) >
          erd::api::memory_estimate(erd::api::Method::erdgpi, 256, 256, opt));

    // Exact modes on a constant image, where GPI stops at the four corners.
    erd::Image flat(16, 16, 255);
    for (auto& s : flat.samples) s = 77;
    erd::api::Options o;
    o.generate.points = 20;
    erd::api::GenerateInfo info;
    st = erd::api::generate(erd::api::Method::gpi, erd::api::view_of(flat), o, &model, &info);
    CHECK(st.code == erd::Code::density);
    CHECK(st.message == "target sampling density not achieved exactly (requested 20 but got 4)");
    CHECK(model.vertices.size() == 4);
    o.exact = erd::api::ExactMode::warn;
    REQUIRE(erd::api::generate(erd::api::Method::gpi, erd::api::view_of(flat), o, &model, &info));
    CHECK(info.warning == st.message);
    o.exact = erd::api::ExactMode::ignore;
    REQUIRE(erd::api::generate(erd::api::Method::gpi, erd::api::view_of(flat), o, &model, &info));
    CHECK(info.warning.empty());
    CHECK(info.requested == 20);
    CHECK(info.achieved == 4);
}

TEST_CASE("public API: triangulate() rebuilds the model's triangulation in the kernel", "[packaging]") {
    erd::Image im = synth_image(40, 32, 8, 5);
    for (auto method : {erd::api::Method::gpi, erd::api::Method::erdgpi}) {
        INFO(erd::api::method_name(method));
        erd::api::Options opt;
        erd::Model model;
        REQUIRE(erd::api::generate(method, erd::api::view_of(im), opt, &model));
        erd::Cdt cdt;
        REQUIRE(erd::api::triangulate(model, &cdt));
        std::string why;
        CHECK(cdt.verify_topology(&why));  // the ERD default's flips leave non-Delaunay faces
        INFO(why);
        CHECK(cdt.vertex_count() == model.vertices.size());
        CHECK(cdt.face_count() == model.faces.size());
        // Same faces as point triples.
        CHECK(erd::canonical_faces(cdt) == erd::canonical_faces(model.vertices, model.faces));
    }
    erd::Model empty;
    erd::Cdt cdt;
    CHECK(erd::api::triangulate(empty, &cdt).code == erd::Code::input);
}

