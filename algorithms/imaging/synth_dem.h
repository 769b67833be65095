// A deterministic synthetic elevation model (issue 47): float heights in metres, with what real
// terrain and its rasters have: smooth relief at several scales (value noise, six octaves), cliffs
// (three straight faults, and a mesa with a vertical rim: steps between two pixels, where explicit
// discontinuities pay) and nodata (lakes and an unsurveyed corner). Made row by row, so a raster
// larger than memory can be written as it is made (`erd synth --kind dem`).
//
// The same parameters give the same heights everywhere: + - * / and sqrt only, hashed lattice
// values from splitmix64, the geometry in exact integers, each height rounded to float32.
#pragma once
#include <cstdint>

namespace erd {

struct DemParams {
    int width = 512;
    int height = 512;
    std::uint64_t seed = 1;
    bool holes = true;  // nodata lakes and corner (NaN); false: every pixel valid
};

// Row y (0 <= y < height) of the model into row[0 .. width-1]: heights in metres, NaN for nodata.
void dem_row(const DemParams& p, int y, double* row);

}  // namespace erd
