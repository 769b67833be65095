// Real-valued rasters (issue 47): TIFF and PFM in and out, real images through every method, the
// valid region of an image with nodata, real models in files, glTF. The end-to-end checks on real
// elevation data (with numpy as the judge) are tests/raster_test.sh's.
#include <catch2/catch.hpp>
#include <tiffio.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "algorithms/imaging/real_image.h"
#include "algorithms/imaging/valid_region.h"
#include "algorithms/methods/greedy_models.h"
#include "algorithms/methods/methods.h"
#include "algorithms/methods/minimax_fit.h"
#include "algorithms/model/metrics.h"
#include "algorithms/model/model_io.h"
#include "algorithms/model/reconstruct.h"
#include "algorithms/output/export.h"
#include "imageio/pfm.h"
#include "imageio/raster_window.h"
#include "imageio/tiff.h"
#include "kernel/raster.h"
#include "tests/decode_util.h"
#include "tests/erd_run.h"

namespace {

using erd::Image;
using erd::SampleType;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// v as a sample of type T: an integer type through int64 (a negative value wraps around in an
// unsigned type, as defined; a double straight to an unsigned type would be undefined there).
template <class T>
T sample_cast(double v) {
    if constexpr (std::is_integral_v<T>) return T(std::int64_t(v));
    else return T(v);
}

// A TIFF written by libtiff (not by erd) of w x h pixels of C channels: value(x, y, c) as type t,
// in strips of `rows` rows or tiles of 16 x 16, contiguous or planar, with `compression`.
template <class T>
std::string libtiff_file(const erd_test::TempDir& dir, int w, int h, int C, std::uint16_t fmt, bool tiles, bool planar,
                         std::uint16_t compression, double (*value)(int, int, int)) {
    const std::string path = dir.file("t.tif");
    TIFF* t = TIFFOpen(path.c_str(), "w");
    REQUIRE(t);
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, std::uint32_t(w));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, std::uint32_t(h));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(C));
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, std::uint16_t(8 * sizeof(T)));
    TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, fmt);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, C == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, planar ? PLANARCONFIG_SEPARATE : PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_COMPRESSION, compression);
    const int planes = planar ? C : 1, per = planar ? 1 : C;
    if (tiles) {
        TIFFSetField(t, TIFFTAG_TILEWIDTH, 16u);
        TIFFSetField(t, TIFFTAG_TILELENGTH, 16u);
        std::vector<T> tile(16 * 16 * std::size_t(per));
        for (int p = 0; p < planes; ++p)
            for (int ty = 0; ty < h; ty += 16)
                for (int tx = 0; tx < w; tx += 16) {
                    for (int y = 0; y < 16; ++y)
                        for (int x = 0; x < 16; ++x)
                            for (int c = 0; c < per; ++c)
                                tile[std::size_t((y * 16 + x) * per + c)] =
                                    sample_cast<T>(tx + x < w && ty + y < h ? value(tx + x, ty + y, planar ? p : c) : 0);
                    REQUIRE(TIFFWriteTile(t, tile.data(), std::uint32_t(tx), std::uint32_t(ty), 0, tsample_t(p)) >= 0);
                }
    } else {
        TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, 3u);
        std::vector<T> row(std::size_t(w) * std::size_t(per));
        for (int p = 0; p < planes; ++p)
            for (int y = 0; y < h; ++y) {
                for (int x = 0; x < w; ++x)
                    for (int c = 0; c < per; ++c) row[std::size_t(x * per + c)] = sample_cast<T>(value(x, y, planar ? p : c));
                REQUIRE(TIFFWriteScanline(t, row.data(), std::uint32_t(y), tsample_t(p)) >= 0);
            }
    }
    TIFFClose(t);
    return erd_test::slurp(path);
}

double ramp(int x, int y, int c) { return (x * 7 - y * 5 + c * 11) * 0.25 - 3; }

template <class T>
void check_type(SampleType type, std::uint16_t fmt) {
    erd_test::TempDir dir;
    for (int C : {1, 3})
        for (bool tiles : {false, true})
            for (bool planar : {false, true})
                for (std::uint16_t comp : {std::uint16_t(COMPRESSION_NONE), std::uint16_t(COMPRESSION_ADOBE_DEFLATE),
                                           std::uint16_t(COMPRESSION_LZW), std::uint16_t(COMPRESSION_PACKBITS)}) {
                    if (C == 1 && planar) continue;
                    INFO("type " << erd::sample_type_name(type) << " channels " << C << " tiles " << tiles << " planar " << planar
                                 << " compression " << comp);
                    const int w = 37, h = 21;
                    const std::string bytes = libtiff_file<T>(dir, w, h, C, fmt, tiles, planar, comp, ramp);
                    Image im;
                    std::string warning;
                    REQUIRE(erd::imageio::decode_tiff(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &im, &warning).ok());
                    CHECK(im.width == w);
                    CHECK(im.height == h);
                    CHECK(im.channels == C);
                    CHECK(im.meta.type == type);
                    const bool integer = type == SampleType::u8 || type == SampleType::u16;
                    CHECK(im.real() == !integer);
                    for (int y = 0; y < h; ++y)
                        for (int x = 0; x < w; ++x)
                            for (int c = 0; c < C; ++c)
                                REQUIRE(erd::sample_value(im, std::size_t((y * w + x) * C + c)) == double(sample_cast<T>(ramp(x, y, c))));
                    // A window is the same part of the whole.
                    erd::imageio::TiffReader r;
                    REQUIRE(r.open(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()).ok());
                    Image part;
                    REQUIRE(r.read(5, 4, 30, 19, &part).ok());
                    CHECK(part.width == 25);
                    CHECK(part.height == 15);
                    for (int y = 0; y < 15; ++y)
                        for (int x = 0; x < 25; ++x)
                            REQUIRE(erd::sample_value(part, std::size_t((y * 25 + x) * C)) == double(sample_cast<T>(ramp(x + 5, y + 4, 0))));
                }
}

// A w x h real image from values (NaN: nodata).
Image real_image(int w, int h, std::vector<double> v, int C = 1) {
    Image im;
    erd::RasterMeta meta;
    meta.type = SampleType::f32;
    REQUIRE(erd::make_real_image(w, h, C, std::move(v), meta, &im).ok());
    return im;
}

// A terrain-like test surface with a cliff, and (holes) two patches of nodata.
Image terrain(int w, int h, bool holes) {
    std::vector<double> v(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double z = 120.5 + 0.37 * x - 0.21 * y + 9.0 * std::sin(x * 0.11) * std::cos(y * 0.07) + (x + y > 70 ? 40.0 : 0.0);
            if (holes && ((x - 20) * (x - 20) + (y - 15) * (y - 15) < 36 || (x > 50 && y < 6))) z = kNaN;
            v[std::size_t(y * w + x)] = z;
        }
    return real_image(w, h, std::move(v));
}

}  // namespace

TEST_CASE("TIFF: every sample type, strips and tiles, planar, compressions read exactly", "[real][io]") {
    check_type<std::uint8_t>(SampleType::u8, SAMPLEFORMAT_UINT);
    check_type<std::uint16_t>(SampleType::u16, SAMPLEFORMAT_UINT);
    check_type<std::uint32_t>(SampleType::u32, SAMPLEFORMAT_UINT);
    check_type<std::int16_t>(SampleType::i16, SAMPLEFORMAT_INT);
    check_type<std::int32_t>(SampleType::i32, SAMPLEFORMAT_INT);
    check_type<float>(SampleType::f32, SAMPLEFORMAT_IEEEFP);
    check_type<double>(SampleType::f64, SAMPLEFORMAT_IEEEFP);
}

TEST_CASE("TIFF and PFM written by erd read back: values, type, holes, nodata, georeferencing", "[real][io]") {
    Image im = terrain(41, 29, true);
    im.meta.geo.pixel_scale = {10, 10, 0};
    im.meta.geo.tiepoints = {0, 0, 0, 500000.5, 5200000.25, 0};
    im.meta.geo.keys = {1, 1, 0, 2, 1024, 0, 1, 1, 3072, 0, 1, 32633};
    im.meta.geo.ascii = "WGS 84 / UTM 33N|";
    for (SampleType t : {SampleType::f32, SampleType::f64, SampleType::i16, SampleType::i32}) {
        im.meta.type = t;
        im.meta.has_nodata = t != SampleType::f32;
        im.meta.nodata = -9999;
        std::string bytes;
        REQUIRE(erd::imageio::encode_tiff(im, &bytes).ok());
        Image back;
        std::string w;
        REQUIRE(erd::imageio::decode_tiff(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &back, &w).ok());
        CHECK(back.meta.type == t);
        CHECK(back.meta.geo == im.meta.geo);
        CHECK(back.valid == im.valid);
        CHECK(back.meta.has_nodata == im.meta.has_nodata);
        for (std::size_t i = 0; i < im.pixels(); ++i) {
            if (!erd::pixel_valid(im, i)) continue;
            const double want = t == SampleType::f32 ? double(float(im.reals[i])) : t == SampleType::f64 ? im.reals[i] : std::round(im.reals[i]);
            REQUIRE(back.reals[i] == want);
        }
    }
    std::string pfm;
    REQUIRE(erd::imageio::encode_pfm(im, &pfm).ok());
    Image back;
    std::string w;
    REQUIRE(erd::imageio::decode_pfm(reinterpret_cast<const unsigned char*>(pfm.data()), pfm.size(), &back, &w).ok());
    CHECK(back.valid == im.valid);
    for (std::size_t i = 0; i < im.pixels(); ++i)
        if (erd::pixel_valid(im, i)) REQUIRE(back.reals[i] == double(float(im.reals[i])));
}

TEST_CASE("hostile TIFFs and PFMs: one line each, never a crash", "[real][io][robust]") {
    const std::string dir = "fuzz/corpus/fuzz_tiff/";
    if (!erd_test::have_input(erd_test::exists(dir + "truncated"), "the fuzz_tiff seeds (run from the repository root)")) return;
    const std::pair<const char*, const char*> cases[] = {
        {"truncated", "TIFF"},
        {"lying_offsets", "cannot be decoded"},
        {"huge_30000", "above the limit"},
        {"huge_side", "above the limit"},
        {"planar_5_samples", "5 samples per pixel"},
        {"palette_1bit_float", "1-bit float samples"},
        {"i8", "8-bit signed samples"},
        {"cmyk", "CMYK"},
        {"unknown_compression", "compression 50123"},
        {"all_nodata", "every pixel is nodata"},
        {"infinity", "infinity"},
        {"nodata_text", "GDAL_NODATA"},
        {"no_width", "TIFF"},
    };
    for (const auto& c : cases) {
        INFO(c.first);
        Image im;
        erd_test::check_refused(erd_test::decode(erd_test::slurp(dir + c.first), &im), c.second);
    }
    Image im;
    erd_test::check_refused(erd_test::decode("Pf\n4 4\n-1.0\n" + std::string(20, '\0'), &im), "PFM raster truncated");
    erd_test::check_refused(erd_test::decode("Pf\n4 4\n0\n" + std::string(64, '\0'), &im), "scale");
}

TEST_CASE("the valid region's outline: between valid and nodata pixels, never through a pixel centre", "[real]") {
    const int w = 23, h = 17;
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        std::vector<std::uint8_t> valid(std::size_t(w * h));
        std::uint32_t r = seed * 2654435761u;
        for (auto& v : valid) {
            r = r * 1664525u + 1013904223u;
            v = (r >> 28) < 11;  // about 70% valid, in speckles
        }
        for (const erd::Polyline& pl : erd::valid_outline(valid, w, h))
            for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
                const erd::LatticePoint a = pl[i], b = pl[i + 1];
                REQUIRE(((a.x & 1) ^ (a.y & 1)) == 1);  // a midpoint of two pixels
                const int n = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
                for (int k = 0; k <= n; ++k) {
                    const int X = a.x + (b.x - a.x) * k / n, Y = a.y + (b.y - a.y) * k / n;
                    REQUIRE_FALSE(((X & 1) == 0 && (Y & 1) == 0));
                }
            }
    }
}

// The removal methods (issue 45: gpr, gprfs, id, erdgpr) refuse a real image with one clear
// Code::input line naming the methods that take it; true for them (checked here), false for the
// others.
static bool refuses_real(const erd::MethodInfo& method, const Image& im, const erd::GenerateOptions& o) {
    const std::string name = method.name;
    if (name != "gpr" && name != "gprfs" && name != "id" && name != "erdgpr") return false;
    erd::GenerateResult res;
    const erd::Status st = method.run(im, o, &res);
    CHECK(st.code == erd::Code::input);
    CHECK_THAT(st.message, Catch::Contains(name + ": real-valued rasters are not supported") && Catch::Contains("use gpi or erdgpi"));
    return true;
}

TEST_CASE("every method meshes a real image with nodata: faces own its valid pixels, none of its holes", "[real]") {
    const Image im = terrain(64, 40, true);
    std::size_t count = 0;
    const erd::MethodInfo* table = erd::methods(&count);
    for (std::size_t k = 0; k < count; ++k) {
        INFO(table[k].name);
        erd::GenerateOptions o;
        o.density = 8;
        o.density_given = true;
        erd::GenerateResult res;
        if (refuses_real(table[k], im, o)) continue;
        REQUIRE(table[k].run(im, o, &res).ok());
        const erd::Model& m = res.model;
        CHECK(m.real);
        CHECK(m.holes);
        CHECK(m.maxval == 0u);
        CHECK(m.lo == im.lo);
        std::vector<int> owners(im.pixels(), 0);
        std::vector<erd::Span> spans;
        for (const auto& f : m.faces) {
            erd::scan_triangle(erd::Lattice::pixels(), {2 * m.width - 2, 2 * m.height - 2}, m.vertices[f[0]], m.vertices[f[1]],
                               m.vertices[f[2]], &spans);
            for (const erd::Span& s : spans)
                for (int x = s.x_begin; x <= s.x_end; ++x) ++owners[std::size_t(s.y * m.width + x)];
        }
        for (std::size_t i = 0; i < im.pixels(); ++i) REQUIRE(owners[i] == (erd::pixel_valid(im, i) ? 1 : 0));
        // Its reconstruction has data exactly at the valid pixels, and its PSNR is over them.
        Image rec;
        REQUIRE(erd::reconstruct(m, erd::supersampled(m), &rec).ok());
        CHECK(rec.valid == im.valid);
        double db = 0;
        REQUIRE(erd::psnr(im, rec, &db).ok());
        CHECK(db > 20);
    }
}

TEST_CASE("--max-error on a real image is a bound on the model, for every method", "[real]") {
    const Image im = terrain(60, 44, true);
    std::size_t count = 0;
    const erd::MethodInfo* table = erd::methods(&count);
    for (std::size_t k = 0; k < count; ++k) {
        INFO(table[k].name);
        erd::GenerateOptions o;
        o.density = std::string(table[k].name) == "ed" || std::string(table[k].name) == "erded" ? 3 : 100;
        o.density_given = true;
        o.max_error = 0.75;
        erd::GenerateResult res;
        if (refuses_real(table[k], im, o)) continue;
        REQUIRE(table[k].run(im, o, &res).ok());
        Image rec;
        REQUIRE(erd::reconstruct(res.model, false, &rec).ok());
        double e = -1;
        REQUIRE(erd::max_abs_error(im, rec, &e).ok());
        CHECK(e <= 0.75);
        // The ERD methods measure on the mesh's own planes (reconstruct's arithmetic differs in
        // the last bits), the others on the reconstruction.
        CHECK(res.stats.raster.max_error == Approx(e).epsilon(1e-12));
    }
}

TEST_CASE("greedy on a real image with the pixel owners: the same mesh, and the owners kept", "[real]") {
    const Image im = terrain(60, 44, true);
    // A coarse mesh first (the state the last insertions of ERDGPI start from), then the same
    // continuation without and with the owner map.
    erd::Cdt start;
    REQUIRE(start.reset(2 * im.width - 2, 2 * im.height - 2).ok());
    erd::ErdModel m0(im, erd::WedgeValueOptions{});
    m0.assign_all(start);
    erd::ErdGreedyModel g0(m0);
    erd::GreedyOptions go;
    go.round_values = false;
    go.max_error_first = true;
    go.max_error = 2.0;
    go.target_vertices = im.pixels();
    erd::GreedyStats gs;
    REQUIRE(erd::greedy_refine(start, im, g0, go, &gs).ok());
    go.max_error = 0.3;
    erd::Cdt plain = start, mapped = start;
    erd::ErdModel mp(im, erd::WedgeValueOptions{}), mm(im, erd::WedgeValueOptions{});
    mp.assign_all(plain);
    mm.assign_all(mapped);
    erd::ErdGreedyModel gp(mp), gm(mm);
    erd::GreedyStats sp, sm;
    REQUIRE(erd::greedy_refine(plain, im, gp, go, &sp).ok());
    std::vector<erd::FaceInd> owners = erd::pixel_owners(mapped, im);
    go.owners = &owners;
    REQUIRE(erd::greedy_refine(mapped, im, gm, go, &sm).ok());
    CHECK(sm.insertions > 100);
    CHECK(sm.insertions == sp.insertions);
    CHECK(sm.total_squared_error == sp.total_squared_error);
    CHECK(mapped.points() == plain.points());
    CHECK(owners == erd::pixel_owners(mapped, im));  // every re-scan kept them
    CHECK(erd::largest_error(mapped, im, mm, &owners) == erd::largest_error(plain, im, mp));
    CHECK(erd::largest_error(mapped, im, mm) <= 0.3);
}

TEST_CASE("ERD step 1 on a real image with --max-error: no simple-image test, the cliff test decides", "[real]") {
    const Image im = terrain(60, 44, true);
    for (const char* name : {"erdgpi", "erded"}) {
        INFO(name);
        const erd::MethodInfo* m = erd::find_method(name);
        REQUIRE(m);
        erd::GenerateOptions o;
        o.density = std::string(name) == "erded" ? 3 : 100;
        o.density_given = true;
        erd::GenerateResult free_n, bounded, all_edges;
        REQUIRE(m->run(im, o, &free_n).ok());
        CHECK(free_n.stats.erd.params.simple_test_beta > 0);  // the test ran without a bound
        o.max_error = 0.75;
        REQUIRE(m->run(im, o, &bounded).ok());
        CHECK(bounded.stats.erd.params.simple_test_beta == 0);
        CHECK_FALSE(bounded.stats.erd.params.simple);
        CHECK(bounded.stats.raster.max_error <= 0.75);
        o.min_step_factor = 0;  // every detected edge kept: the simple test decides again
        REQUIRE(m->run(im, o, &all_edges).ok());
        CHECK(all_edges.stats.erd.params.simple_test_beta > 0);
    }
}

TEST_CASE("a real model's file: header keys read back, the same bytes written again", "[real][model]") {
    Image im = terrain(30, 20, true);
    im.meta.geo.pixel_scale = {0.5, 0.25, 0};
    im.meta.geo.tiepoints = {0, 0, 0, -84.25, 36.5, 0};
    im.meta.geo.ascii = "a b#c%d";
    im.meta.has_nodata = true;
    im.meta.nodata = -32768;
    im.meta.type = SampleType::i16;
    for (const char* method : {"gpi", "erdgpi"}) {
        erd::GenerateOptions o;
        o.density = 10;
        o.density_given = true;
        erd::GenerateResult res;
        REQUIRE(erd::find_method(method)->run(im, o, &res).ok());
        std::string text, again;
        REQUIRE(erd::write_model(res.model, &text).ok());
        erd::Model back;
        REQUIRE(erd::read_model(text, erd::ModelFileKind::unknown, &back).ok());
        CHECK(back.real);
        CHECK(back.holes);
        CHECK(back.lo == res.model.lo);
        CHECK(back.hi == res.model.hi);
        CHECK(back.meta.type == SampleType::i16);
        CHECK(back.meta.nodata == -32768);
        CHECK(back.meta.geo == im.meta.geo);
        CHECK(back.width == 30);
        CHECK(back.height == 20);
        REQUIRE(erd::write_model(back, &again).ok());
        CHECK(again == text);
        // The same image from both.
        Image a, b;
        REQUIRE(erd::reconstruct(res.model, false, &a).ok());
        REQUIRE(erd::reconstruct(back, false, &b).ok());
        CHECK(a.reals == b.reals);
    }
}

TEST_CASE("glTF: the GLB container, its chunks and its counts", "[real][output]") {
    const Image im = terrain(40, 30, true);
    erd::GenerateOptions o;
    o.density = 10;
    o.density_given = true;
    erd::GenerateResult res;
    REQUIRE(erd::find_method("erdgpi")->run(im, o, &res).ok());
    erd::ExportOptions eo;
    eo.format = erd::MeshFormat::glb;
    std::string glb;
    erd::ExportCounts counts;
    REQUIRE(erd::export_mesh(res.model, eo, &glb, &counts).ok());
    REQUIRE(glb.size() > 28);
    const auto u32 = [&](std::size_t at) {
        std::uint32_t v;
        std::memcpy(&v, glb.data() + at, 4);
        return v;
    };
    CHECK(glb.compare(0, 4, "glTF") == 0);
    CHECK(u32(4) == 2u);
    CHECK(u32(8) == glb.size());
    const std::uint32_t json = u32(12);
    CHECK(u32(16) == 0x4E4F534Au);
    CHECK(json % 4 == 0u);
    const std::string text = glb.substr(20, json);
    CHECK_THAT(text, Catch::Contains("\"count\":" + std::to_string(counts.vertices)));
    CHECK_THAT(text, Catch::Contains("\"count\":" + std::to_string(3 * counts.faces)));
    CHECK(u32(20 + json + 4) == 0x004E4942u);
    CHECK(20 + json + 8 + u32(20 + json) == glb.size());
    CHECK(counts.faces == res.model.faces.size());
}

TEST_CASE("an unsigned 16-bit TIFF without nodata is an integer image: the same model as its PGM", "[real]") {
    erd_test::TempDir dir;
    const std::string tiff = libtiff_file<std::uint16_t>(dir, 48, 32, 1, SAMPLEFORMAT_UINT, false, false, COMPRESSION_LZW,
                                                          [](int x, int y, int) { return double((x * 977 + y * 131) % 60000); });
    Image a;
    REQUIRE(erd_test::decode(tiff, &a).ok());
    CHECK_FALSE(a.real());
    CHECK(a.maxval == 65535u);
    Image b(48, 32, 65535);
    b.samples = a.samples;
    for (const char* method : {"gpi", "erdgpi"}) {
        erd::GenerateOptions o;
        erd::GenerateResult ra, rb;
        REQUIRE(erd::find_method(method)->run(a, o, &ra).ok());
        REQUIRE(erd::find_method(method)->run(b, o, &rb).ok());
        std::string ta, tb;
        REQUIRE(erd::write_model(ra.model, &ta).ok());
        REQUIRE(erd::write_model(rb.model, &tb).ok());
        CHECK(ta == tb);
    }
}
