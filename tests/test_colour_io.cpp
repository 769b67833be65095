// Colour images in and out (issues 17, 20): PPM P3/P6 8- and 16-bit, PNG RGB/RGBA 8- and 16-bit,
// JPEG (the committed seeds of fuzz/corpus/fuzz_jpeg), colour whose channels are equal becoming
// gray, --gray, colour PSNR and erd info on colour. Small images only: the whole file runs in
// well under a second.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "algorithms/imaging/luma.h"
#include "algorithms/model/metrics.h"
#include "cli/image_io.h"
#include "imageio/image_file.h"
#include "tests/decode_util.h"
#include "tests/erd_run.h"
#include "tests/png_util.h"

using erd::Image;
using erd::cli::ImageFormat;
using namespace erd_test;

namespace {

// A w x h colour image whose samples follow a fixed pattern below maxval, channels different.
Image pattern(int w, int h, std::uint32_t maxval) {
    Image im(w, h, maxval, 3);
    for (std::size_t k = 0; k < im.samples.size(); ++k) im.samples[k] = std::uint16_t((k * 7919 + k / 3 * 31) % (maxval + 1));
    im.samples[1] = std::uint16_t(im.samples[0] == 0 ? 1 : 0);  // pixel 0 not gray
    return im;
}

}  // namespace

TEST_CASE("PPM P6 and P3, 8- and 16-bit, round trip exactly", "[io][colour]") {
    for (std::uint32_t maxval : {255u, 100u, 1000u, 65535u}) {
        for (bool plain : {false, true}) {
            INFO("maxval " << maxval << (plain ? " plain" : " raw"));
            Image im = pattern(5, 3, maxval);
            std::string bytes = erd::cli::encode_pnm(im, plain);
            CHECK(bytes.substr(0, 2) == (plain ? "P3" : "P6"));
            if (!plain) CHECK(bytes.size() == std::string("P6\n5 3\n").size() + std::to_string(maxval).size() + 1 + 45 * (maxval > 255 ? 2 : 1));
            Image back;
            ImageFormat f;
            REQUIRE(decode(bytes, &back, nullptr, &f).ok());
            CHECK(f == (plain ? ImageFormat::ppm_plain : ImageFormat::ppm_raw));
            CHECK(back.channels == 3);
            CHECK(back.maxval == maxval);
            CHECK(back.samples == im.samples);
        }
    }
}

TEST_CASE("PAM (P7): gray, RGB, alpha dropped with a warning, 16-bit; bad headers one line", "[io][colour]") {
    Image im;
    std::string w;
    ImageFormat f;
    REQUIRE(decode(std::string("P7\nWIDTH 2\nHEIGHT 1\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n\1\2\3\377\4\5\6\1"),
                   &im, &w, &f).ok());
    CHECK(f == ImageFormat::pam);
    CHECK(im.channels == 3);
    CHECK(im.samples == std::vector<std::uint16_t>{1, 2, 3, 4, 5, 6});
    CHECK(w == "PAM alpha channel ignored (erd meshes the colour or gray channels only)");
    REQUIRE(decode(std::string("P7\n# c\nWIDTH 1\nHEIGHT 2\nDEPTH 1\nMAXVAL 1000\nENDHDR\n\x03\xe8\x00\x07", 55), &im, &w).ok());
    CHECK(im.channels == 1);
    CHECK(im.maxval == 1000);
    CHECK(im.samples == std::vector<std::uint16_t>{1000, 7});
    struct Bad { const char* bytes; const char* fragment; };
    for (const Bad& b : {Bad{"P7\nWIDTH 2\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\nENDHDR\n\1", "raster truncated: expected 2 bytes"},
                         Bad{"P7\nWIDTH 1\nHEIGHT 1\nDEPTH 5\nMAXVAL 255\nENDHDR\n\1\1\1\1\1", "PAM DEPTH 5"},
                         Bad{"P7\nWIDTH 1\nDEPTH 1\nMAXVAL 255\nENDHDR\n\1", "PAM header has no HEIGHT line"},
                         Bad{"P7\nWIDTH 1\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\n", "no ENDHDR line"},
                         Bad{"P7\nWIDTH x1\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\nENDHDR\n", "junk where the PAM WIDTH belongs"}}) {
        INFO(b.bytes);
        check_refused(decode(b.bytes, &im), b.fragment);
    }
}

TEST_CASE("16-bit P6 samples are big-endian, interleaved R G B", "[io][colour]") {
    Image im(1, 1, 1000, 3);
    im.samples = {0x0102, 999, 0};
    CHECK(erd::cli::encode_pnm(im, false) == std::string("P6\n1 1\n1000\n\x01\x02\x03\xe7\x00\x00", 18));
}

TEST_CASE("PNG RGB out and back: 8-bit, 16-bit, through files and by name", "[io][colour]") {
    TempDir dir;
    for (std::uint32_t maxval : {255u, 65535u}) {
        INFO("maxval " << maxval);
        Image im = pattern(7, 4, maxval);
        REQUIRE(erd::cli::write_image(dir.file("c.png"), im).ok());
        const std::string bytes = slurp(dir.file("c.png"));
        CHECK(int(bytes[24]) == (maxval > 255 ? 16 : 8));  // IHDR bit depth
        CHECK(int(bytes[25]) == 2);                         // colour type RGB
        Image back;
        std::string w;
        ImageFormat f;
        REQUIRE(erd::cli::read_image(dir.file("c.png"), &back, &w, &f).ok());
        CHECK(f == ImageFormat::png);
        CHECK(back.channels == 3);
        CHECK(back.samples == im.samples);
        CHECK(w.empty());
        // Any other name: PPM.
        REQUIRE(erd::cli::write_image(dir.file("c.out"), im).ok());
        REQUIRE(erd::cli::read_image(dir.file("c.out"), &back, &w, &f).ok());
        CHECK(f == ImageFormat::ppm_raw);
        CHECK(back.samples == im.samples);
    }
    // The library's own file functions (imageio/image_file.h).
    Image im = pattern(3, 3, 255), back;
    REQUIRE(erd::imageio::write_image_file(dir.file("lib.png"), im).ok());
    REQUIRE(erd::imageio::read_image_file(dir.file("lib.png"), &back).ok());
    CHECK(back.samples == im.samples);
    erd::Status s = erd::imageio::read_image_file(dir.file("missing.png"), &back);
    CHECK(s.code == erd::Code::input);
    CHECK_THAT(s.message, Catch::Contains("missing.png: cannot open"));
}

TEST_CASE("colour whose three channels are equal everywhere becomes gray", "[io][colour]") {
    Image back;
    REQUIRE(decode("P6 2 1 255\n\x05\x05\x05\x09\x09\x09", &back).ok());
    CHECK(back.channels == 1);
    CHECK(back.samples == std::vector<std::uint16_t>{5, 9});
    REQUIRE(decode("P3 2 1 1000 7 7 7 999 999 999\n", &back).ok());
    CHECK(back.channels == 1);
    CHECK(back.samples == std::vector<std::uint16_t>{7, 999});
    REQUIRE(decode(make_png(2, 1, 8, 2, std::string("\x01\x01\x01\x02\x02\x02", 6)), &back).ok());
    CHECK(back.channels == 1);
    CHECK(back.samples == std::vector<std::uint16_t>{1, 2});
    // One differing sample keeps colour.
    REQUIRE(decode("P6 2 1 255\n\x05\x05\x05\x09\x09\x08", &back).ok());
    CHECK(back.channels == 3);
}

// A progressive JPEG whose scans leave coefficients unwritten (found by the fuzz campaign through
// fuzz_framing: the same bytes decoded twice in one process gave two answers). The decoder's
// allocations start zeroed (third_party/stb_glue.cpp), so what the heap held before cannot show:
// the heap is filled with two patterns (blocks of the decoder's sizes, written, freed, then taken
// again by the decoder) and the two decodes must agree, status, message and samples.
TEST_CASE("JPEG: a progressive file with unwritten coefficients decodes the same whatever the heap held", "[io][jpeg]") {
    const std::string f = "fuzz/corpus/fuzz_jpeg/regress_progressive_unwritten_coefficients";
    if (!have_input(exists(f), f + " not found: run the tests from the repository root")) return;
    const std::string bytes = slurp(f);
    auto decode_after = [&](unsigned char pattern, Image* im, std::string* message) {
        std::vector<void*> blocks;
        for (std::size_t size : {64u, 128u, 256u, 512u, 1024u, 2048u, 4096u, 8192u, 16384u, 32768u, 65536u})
            for (int k = 0; k < 4; ++k) {
                void* p = std::malloc(size);
                REQUIRE(p != nullptr);
                std::memset(p, pattern, size);
                blocks.push_back(p);
            }
        for (void* p : blocks) std::free(p);
        const erd::Status st = decode(bytes, im);
        *message = st.message;
        return st.ok();
    };
    Image a, b;
    std::string ma, mb;
    const bool oka = decode_after(0x00, &a, &ma), okb = decode_after(0x5a, &b, &mb);
    CHECK(oka == okb);
    CHECK(ma == mb);
    if (oka && okb) CHECK(a.samples == b.samples);
}

TEST_CASE("JPEG seeds: gray, colour 4:2:0 and 4:4:4, progressive 1xN, equal channels; hostile ones refused", "[io][colour]") {
    const std::string d = "fuzz/corpus/fuzz_jpeg/";
    if (!have_input(exists(d + "gray_8x8.jpg"), d + " not found: run the tests from the repository root")) return;
    struct Good { const char* file; int w, h, channels; };
    for (const Good& g : {Good{"gray_8x8.jpg", 8, 8, 1}, Good{"rgb_16x8_420.jpg", 16, 8, 3}, Good{"rgb_12x10_444.jpg", 12, 10, 3},
                          Good{"progressive_1x7.jpg", 1, 7, 3}, Good{"rgb_equal_8x8.jpg", 8, 8, 1}, Good{"gray_9x1.jpg", 9, 1, 1}}) {
        INFO(g.file);
        Image im;
        ImageFormat f;
        std::string w;
        REQUIRE(decode(slurp(d + g.file), &im, &w, &f).ok());
        CHECK(f == ImageFormat::jpeg);
        CHECK(im.width == g.w);
        CHECK(im.height == g.h);
        CHECK(im.channels == g.channels);
        CHECK(im.maxval == 255);
        CHECK(w.empty());
    }
    struct Bad { const char* file; const char* fragment; };
    for (const Bad& b : {Bad{"truncated.jpg", "JPEG truncated: no end-of-image marker"},
                         Bad{"cmyk_8x8.jpg", "JPEG has 4 components (CMYK or YCCK)"},
                         Bad{"progressive_huge.jpg", "JPEG 16000 x 16000 in 549 bytes is more than 4096 samples a byte"},
                         Bad{"regress_dht_over_256", "Huffman table (DHT) with 2023 codes (at most 256)"},
                         Bad{"regress_scan_undefined_table", "a scan uses Huffman table AC 1, which no DHT segment before it defines"},
                         Bad{"regress_scan_undefined_quant", "a scan uses quantisation table 0, which no DQT segment before it defines"}}) {
        INFO(b.file);
        Image im;
        check_refused(decode(slurp(d + b.file), &im), b.fragment);
    }
    // A frame header declaring arithmetic coding is named.
    std::string arith = slurp(d + "gray_8x8.jpg");
    const std::size_t sof = arith.find("\xff\xc0");
    REQUIRE(sof != std::string::npos);
    arith[sof + 1] = '\xc9';
    Image im;
    CHECK_THAT(decode(arith, &im).message, Catch::Contains("JPEG is arithmetic-coded"));
    // A baseline scan naming a DC table no DHT defined (the seed defines DC 0 and AC 0 only).
    std::string undefined = slurp(d + "gray_8x8.jpg");
    const std::size_t sos = undefined.find("\xff\xda");
    REQUIRE(sos != std::string::npos);
    REQUIRE(undefined[sos + 6] == '\x00');  // Td/Ta of the one component
    undefined[sos + 6] = '\x20';
    CHECK_THAT(decode(undefined, &im).message, Catch::Contains("a scan uses Huffman table DC 2, which no DHT segment before it defines"));
    // A frame component naming a quantisation table no DQT defined (the seed defines table 0).
    std::string unquant = slurp(d + "gray_8x8.jpg");
    REQUIRE(unquant[sof + 12] == '\x00');  // Tq of the one component
    unquant[sof + 12] = '\x03';
    CHECK_THAT(decode(unquant, &im).message, Catch::Contains("a scan uses quantisation table 3, which no DQT segment before it defines"));
}

TEST_CASE("hostile colour inputs: one line each, Code::input", "[io][colour]") {
    struct Bad { const char* id; std::string bytes; const char* fragment; };
    const Bad bad[] = {
        {"truncated P6", "P6\n4 4 255\nabcdef", "raster truncated: expected 48 bytes (4 x 4 x 3 x 1), found 6"},
        {"maxval 0", std::string("P6\n1 1 0\n\0\0\0", 12), "maxval is 0"},
        {"16-bit odd count", std::string("P6\n1 1 65535\n\0\1\0\2\0", 18), "(an odd count: 16-bit samples take 2 bytes)"},
        {"P3 above maxval", "P3 1 1 9 1 2 10\n", "sample 10 at (0, 0) channel B is above maxval 9"},
        {"P6 above maxval", "P6 2 1 9\n\1\2\3\4\5\12", "sample 10 at (1, 0) channel B is above maxval 9"},
    };
    for (const auto& b : bad) {
        INFO(b.id);
        Image im;
        check_refused(decode(b.bytes, &im), b.fragment);
    }
    Image im;
    REQUIRE(decode("P6 1 1 255\n\1\2\3", &im).ok());  // 1x1 is an image; the commands refuse to mesh it
    CHECK(im.samples == std::vector<std::uint16_t>{1, 2, 3});
    std::string w;
    REQUIRE(decode(make_png(1, 2, 16, 6, be16s({1, 2, 3, 4, 5, 6, 7, 8})), &im, &w).ok());
    CHECK(im.samples == std::vector<std::uint16_t>{1, 2, 3, 5, 6, 7});
    CHECK(w == "PNG alpha channel ignored (erd meshes the colour or gray channels only)");
}

TEST_CASE("colour MSE and PSNR: averaged over channels and pixels; colour against gray is an error", "[io][colour]") {
    Image a(2, 1, 255, 3), b(2, 1, 255, 3);
    a.samples = {10, 20, 30, 40, 50, 60};
    b.samples = {12, 20, 30, 40, 50, 66};  // squared errors 4 (R) and 36 (B)
    double e = 0, per[3] = {0, 0, 0};
    REQUIRE(erd::mse(a, b, &e).ok());
    CHECK(e == Approx(40.0 / 6.0));
    REQUIRE(erd::channel_mse(a, b, per).ok());
    CHECK(per[0] == Approx(2.0));
    CHECK(per[1] == 0.0);
    CHECK(per[2] == Approx(18.0));
    CHECK(erd::psnr(a, b) == Approx(10.0 * std::log10(255.0 * 255.0 / (40.0 / 6.0))));
    Image g(2, 1, 255);
    erd::Status s = erd::mse(a, g, &e);
    CHECK(s.code == erd::Code::input);
    CHECK_THAT(s.message, Catch::Contains("one image is colour and the other gray"));
}

TEST_CASE("erd psnr, info, generate and edges on colour files", "[io][colour][cli]") {
    if (!need_binary()) return;
    TempDir dir;
    Image im(12, 10, 255, 3);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 12; ++x) {
            im.at(x, y, 0) = std::uint16_t(x * 20);
            im.at(x, y, 1) = std::uint16_t(y * 25);
            im.at(x, y, 2) = std::uint16_t(x > 5 ? 200 : 10);
        }
    Image other = im;
    other.at(3, 3, 2) = 40;
    REQUIRE(erd::cli::write_image(dir.file("c.ppm"), im).ok());
    REQUIRE(erd::cli::write_image(dir.file("o.png"), other).ok());
    REQUIRE(erd::cli::write_image(dir.file("l.pgm"), erd::luma(im)).ok());

    RunResult p = run_erd("psnr --channels " + sh_quote(dir.file("c.ppm")) + " " + sh_quote(dir.file("o.png")));
    CHECK(p.status == 0);
    // MSE 900 / 360 samples; B alone 900 / 120.
    CHECK(p.out == "44.1514\nR inf G inf B 39.3802\n");
    RunResult mixed = run_erd("psnr " + sh_quote(dir.file("c.ppm")) + " " + sh_quote(dir.file("l.pgm")));
    CHECK(mixed.status == 2);
    CHECK_THAT(mixed.err, Catch::Contains("one image is colour and the other gray"));
    CHECK(std::count(mixed.err.begin(), mixed.err.end(), '\n') == 1);
    RunResult luma = run_erd("psnr --gray " + sh_quote(dir.file("c.ppm")) + " " + sh_quote(dir.file("l.pgm")));
    CHECK(luma.status == 0);
    CHECK(luma.out == "inf\n");

    RunResult info = run_erd("info --json " + sh_quote(dir.file("c.ppm")));
    CHECK(info.status == 0);
    CHECK_THAT(info.out, Catch::Contains("\"format\":\"ppm-raw\",\"width\":12,\"height\":10,\"maxval\":255"));
    CHECK_THAT(info.out, Catch::Contains("\"channels\":3"));

    // generate on colour: a 3-channel model, no warning; with --gray the luma's mesh, byte for byte.
    RunResult g1 = run_erd("generate -m gpi -n 12 -i " + sh_quote(dir.file("c.ppm")) + " -o " + sh_quote(dir.file("c.model")));
    RunResult g2 = run_erd("generate -q -m gpi -n 12 -i " + sh_quote(dir.file("l.pgm")) + " -o " + sh_quote(dir.file("l.model")));
    RunResult g3 = run_erd("generate -m gpi --gray -n 12 -i " + sh_quote(dir.file("c.ppm")) + " -o " + sh_quote(dir.file("g.model")));
    CHECK(g1.status == 0);
    CHECK(g2.status == 0);
    CHECK(g3.status == 0);
    CHECK_THAT(g1.err, !Catch::Contains("luma"));
    CHECK_THAT(slurp(dir.file("c.model")), Catch::Contains("channels 3"));
    CHECK_THAT(g3.err, !Catch::Contains("luma"));
    CHECK(slurp(dir.file("g.model")) == slurp(dir.file("l.model")));
    RunResult e = run_erd("edges -q --gray " + sh_quote(dir.file("c.ppm")) + " -o " + sh_quote(dir.file("e.pgm")));
    CHECK(e.status == 0);
}
