// Scan conversion: which lattice points a triangle owns, visited as horizontal spans.
//
// Ownership rule (exact, integer arithmetic only). A lattice point p of the closed domain
// [0, max_x] x [0, max_y] (doubled coordinates) belongs to the face whose OPEN interior contains
// the symbolically perturbed point
//     p + (sx*eps, sy*eps^2),  eps -> 0+,
//     sx = -1 if p.x == max_x else +1,   sy = -1 if p.y == max_y else +1.
// The perturbed point always lies in the open domain and on no edge (the direction (sx, sy*eps)
// is parallel to no segment for small eps), so for ANY triangulation of the rectangle every
// lattice point of the closed domain (on edges, at vertices, on the outer boundary) is owned by
// exactly one face. Away from the right and bottom borders this is the familiar top-left rule
// with y pointing down: a point on an edge goes to the face on its right (larger x), a point on a
// horizontal edge to the face below it (larger y). Points outside the closed domain are owned by
// no face.
//
// Per edge a->b of a positively oriented triangle the test is on E(p) = orient2d(a, b, p):
// E > 0, or E == 0 and sx*(a.y - b.y) > 0, or E == 0, a.y == b.y and sy*(b.x - a.x) > 0.
//
// Lattices. A lattice is given in "fine" coordinates, fine = scale * doubled coordinate; its point
// (i, j) is at fine (phase_x + step_x*i, phase_y + step_y*j). One routine serves:
//   pixels():      scale 1, step 2, phase 0: index (i, j) is pixel (x, y) (doubled (2x, 2y));
//   supersample(): scale 4 (fine = 8 * pixel), step 2, phase -3: index i = 4x + k is the
//                  sub-sample at x + (2k - 3)/8, k = 0..3, i.e. offsets -0.375 -0.125 0.125 0.375;
//   the clamping lattices of reconstruction (samples moved onto the border of the domain).
// Fine coordinates must stay below 2^28 in magnitude (doubled coordinates < 2^24, scale <= 4,
// |phase| and step small): every product below is then exact in int64.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "kernel/lattice.h"

namespace erd {

// A regular lattice of sample points (see the header comment).
struct Lattice {
    std::int32_t scale = 1;   // fine coordinate = scale * doubled coordinate
    std::int32_t step_x = 2;  // spacing in fine units, >= 1
    std::int32_t step_y = 2;
    std::int32_t phase_x = 0;  // fine coordinate of index 0
    std::int32_t phase_y = 0;

    std::int64_t fine_x(std::int64_t i) const { return phase_x + step_x * i; }
    std::int64_t fine_y(std::int64_t j) const { return phase_y + step_y * j; }

    // Pixel centres: index (i, j) = pixel (x, y).
    static Lattice pixels() { return Lattice{}; }
    // 4x4 supersampling: index i = 4x + k is the sub-sample at x + (2k - 3)/8 pixel (same in y).
    static Lattice supersample() { return Lattice{4, 2, 2, -3, -3}; }
};

// The domain rectangle [0, max_x] x [0, max_y] in doubled coordinates (max = 2W-2, 2H-2).
struct RasterDomain {
    std::int32_t max_x = 0;
    std::int32_t max_y = 0;
};

// One row of owned lattice points: row index y, column indices x_begin..x_end INCLUSIVE.
struct Span {
    std::int32_t y = 0;
    std::int32_t x_begin = 0;
    std::int32_t x_end = 0;
};

// Clears *out and appends the spans of the lattice points that triangle (a, b, c) owns, rows top
// to bottom (increasing y), never an empty span. The triangle may have either orientation; a
// degenerate (zero-area) triangle owns nothing. Returns the number of points owned. The vector is
// the caller's, so a loop over faces allocates nothing after its first large face.
std::int64_t scan_triangle(const Lattice& lattice, RasterDomain domain, LatticePoint a, LatticePoint b,
                           LatticePoint c, std::vector<Span>* out);

// The same, restricted to lattice rows j_begin..j_end (inclusive): exactly the full scan's spans
// of those rows, at the cost of those rows only (for scanning a mesh in bands of rows).
std::int64_t scan_triangle(const Lattice& lattice, RasterDomain domain, LatticePoint a, LatticePoint b,
                           LatticePoint c, std::vector<Span>* out, std::int32_t j_begin, std::int32_t j_end);

// The same rule for one lattice point (i, j): true when triangle (a, b, c) owns it.
bool triangle_owns(const Lattice& lattice, RasterDomain domain, LatticePoint a, LatticePoint b, LatticePoint c,
                   std::int32_t i, std::int32_t j);

// A linear function through three (point, value) pairs, for evaluating a face's plane along
// spans: v = at(lattice, span.x_begin, span.y), then v += step_x(lattice) per point. Set up
// relative to p0 in doubled coordinates, so values stay accurate far from the origin.
struct SpanPlane {
    double x0 = 0.0;  // doubled coordinates of p0
    double y0 = 0.0;
    double z0 = 0.0;  // value at p0
    double gx = 0.0;  // dz/dX, dz/dY per doubled unit
    double gy = 0.0;

    // The plane through (p0, z0), (p1, z1), (p2, z2); false (and a constant plane z0) when the
    // points are collinear.
    bool set(LatticePoint p0, double z0v, LatticePoint p1, double z1v, LatticePoint p2, double z2v);
    // Value at doubled coordinates (X, Y).
    double at(double X, double Y) const { return z0 + gx * (X - x0) + gy * (Y - y0); }
    // Value at lattice point (i, j).
    double at(const Lattice& l, std::int32_t i, std::int32_t j) const {
        return at(double(l.fine_x(i)) / l.scale, double(l.fine_y(j)) / l.scale);
    }
    // Increment from lattice point (i, j) to (i + 1, j).
    double step_x(const Lattice& l) const { return gx * l.step_x / l.scale; }
};

// The plane of a face whose three corner values are integers in [0, maxval] (every basic model
// erd makes: its values are image samples), rounded half up EXACTLY on the pixel lattice, so a
// value that lies exactly on .5 goes up whatever the face's shape (a running sum of doubles can
// land on either side of it).
//
// With D = |orient2d(p0, p1, p2)| the plane is v = N / D for the integer
//     N(X, Y) = z0*D + a*(X - x0) + b*(Y - y0)    (doubled coordinates; a, b as in SpanPlane),
// and round-half-up(v) = floor(v + 1/2) = floor(t / (4D)) with the ODD integer t = 4N + 2D + 1
// (for integers m and n > 0, floor(m / n) = floor((2m + 1) / (2n))). Every q = t / (4D) is thus
// at least 1/(4D) away from every integer, and a double within 1/(4D) of q truncates to floor(q).
// On a pixel the face owns, 0 <= v <= maxval (the pixel lies in the closed face, where the plane
// stays between its corner values), so 0 < q < maxval + 1 =: V1 and t < 4*V1*D < 2^50 (D < 2^32
// with doubled coordinates <= 65534): t and its steps are exact doubles.
//
// Along a row the scan steps p = t * (1 / 4D) instead of t: p_0 = fl(t_0 * inv), p_k+1 =
// fl(p_k + dp), inv = fl(1/(4D)), dp = fl(dt * inv). With u = 2^-53: p_0 and dp carry relative
// errors <= 2u + u^2, k*|dq| = |q_k - q_0| < V1, and each addition adds <= u*(V1 + tiny), so
//     |p_k - q_k| <= (2u + u^2) V1 + (2u + u^2) V1 + k u (V1 + tiny) < (k + 5) V1 u,
// which is below 1/(4D) while (k + 5) * V1 * D <= 2^51. `run` is the number of pixels one start
// value may be stepped over (4 at the largest image and maxval; ~2.8M on the first faces of an
// 8-bit 1024 x 768 image); a longer span restarts from t, which is exact at every pixel.
struct RoundedPlane {
    std::int64_t t00 = 1;         // t at pixel (0, 0): 4*z0*D + 2D + 1 - 4a*x0 - 4b*y0
    std::int64_t tx = 0, ty = 0;  // t per pixel in x and y: 8a, 8b
    double inv = 0.0;             // fl(1 / (4D))
    double dp = 0.0;              // fl(tx * inv): the step of p from pixel (i, j) to (i + 1, j)
    std::int32_t run = 1;         // pixels one start value may be stepped over (see above)

    // The plane through values z0..z2 at p0..p2; false when the points are collinear or a value
    // is outside [0, maxval] (1 <= maxval <= 65535), the cases the argument above does not cover.
    bool set(LatticePoint p0, std::int64_t z0v, LatticePoint p1, std::int64_t z1v, LatticePoint p2, std::int64_t z2v,
             std::int64_t maxval);
    // t at pixel (i, j), exact (every term is below 2^53 in magnitude).
    std::int64_t t_pixel(std::int64_t i, std::int64_t j) const { return t00 + tx * i + ty * j; }
    // p at pixel (i, j): truncates to the rounded value there, and may be stepped by dp over
    // `run` pixels.
    double p_pixel(std::int64_t i, std::int64_t j) const { return double(t_pixel(i, j)) * inv; }
    // Cuts columns i0..i1 of row j into consecutive pieces of at most `run` pixels and calls
    // fn(first, last, p) for each, p = p_pixel(first, j): stepping p by dp along a piece and
    // truncating gives the rounded value at every pixel of it (the pixels must be the face's).
    template <class Fn>
    void pieces(std::int32_t i0, std::int32_t i1, std::int32_t j, Fn&& fn) const {
        if (i1 - std::int64_t(i0) < run) {  // nearly always: the whole row in one piece
            fn(i0, i1, p_pixel(i0, j));
            return;
        }
        for (std::int64_t first = i0; first <= i1; first += run) {
            const std::int64_t last = std::min<std::int64_t>(i1, first + run - 1);
            fn(std::int32_t(first), std::int32_t(last), p_pixel(first, j));
        }
    }
};

}  // namespace erd
