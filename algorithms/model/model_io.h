// The model files: .model (thesis A.4.1), .erd (A.4.2), the -t triangulation and the -p
// polylines (../shared/spec/NOTES.md).
//
// All four are whitespace-separated text, read leniently (any whitespace, '#' comments to the
// end of the line) and written canonically (one record per line, '\n', values as integers when
// integral, else the shortest decimal that reads back to the same double).
//
//   .model   maxval / NV / NV lines "x y value" (PIXEL coordinates) / NF / NF lines "i j k"
//   .erd     maxval / NV / NV lines "X Y value" (DOUBLED coordinates) / NF / NF lines "i j k" /
//            NW / NW lines "vertex face value" (wedge lines)
//   -t       "erd-triangulation 1" / "W H" / NV / NV lines "X Y" (doubled) / NF / NF lines "i j k" /
//            NC / NC lines "i j" (constrained edges)
//   -p       "erd-polylines 1" / NP / NP lines "n X1 Y1 ... Xn Yn" (DOUBLED coordinates; a closed
//            loop repeats its first point): the simplified polylines of an ERD method's step 1
//
// Faces are written with positive signed area (X1-X0)(Y2-Y0) - (X2-X0)(Y1-Y0) > 0; either
// orientation is accepted on input and fixed. Model files carry maxval but not the image size:
// W = max X / 2 + 1 and H = max Y / 2 + 1 over the vertices, and the four corners of
// [0, 2W-2] x [0, 2H-2] must be vertices.
//
// Wedge lines. The writer lists, for every vertex with more than one wedge, one line per incident
// face (the value of the wedge that face lies in), so the file alone fixes the reconstruction. The
// reader also takes the thesis's one-line-per-wedge form: a face without a line gets the value of
// the nearest listed faces around the vertex when those on both sides agree (or there is only one
// side, at the open end of a border fan); otherwise it stops with "the wedge of face F at vertex
// V is undetermined". For a vertex with wedge lines the value on its vertex line is ignored (thesis
// A.4.2) and Model::values holds the mean of its wedge values; Model::constraints holds the edges
// across which corner values jump (algorithms/model/model_topology.h).
//
// Header block (optional; a file without it is exactly the thesis's format). An extended file
// starts with the line "erd-header 1", then one "key value..." line per key, then the line
// "end", then the thesis's body. Keys: "edges hard|soft" (.erd only; Model::edges, soft when
// absent) and "channels 1|3" (Model::channels, 1 when absent). The writer adds the block only
// when it has something to say (channels 3, edges hard; in that order). A reader refuses a
// version other than 1, a key it does not know (naming it), and a key given twice.
//
// Colour (channels 3): the body is the thesis's with every value replaced by three, red green
// blue, on the same line: vertex lines "x y r g b", wedge lines "vertex face r g b". A record's
// values must all be on its line and nothing may follow them there, so a line with two or four
// values is named ("line 9: vertex 4 has 2 values on its line, expected 3") instead of shifting
// the records after it. An edge is a discontinuity when any channel jumps across it, and a vertex
// needs wedge lines when any channel of a corner differs from its vertex line. A reader without
// colour (erd before it) stops at the header with "unknown header key 'channels'".
//
//     erd-header 1
//     channels 3
//     end
//     255
//     5
//     0 0 10 11 12          <- vertex 0 at (0, 0), doubled: R 10, G 11, B 12
//     4 0 20 21 22
//     0 4 30 31 32
//     4 4 40 41 42
//     2 2 25 26 25          <- vertex 4: ignored for its wedge lines, the mean of its wedges
//     4
//     0 1 4
//     1 3 4
//     3 2 4
//     2 0 4
//     4                     <- vertex 4 has two wedges, differing in blue only
//     4 0 25 26 10
//     4 1 25 26 10
//     4 2 25 26 40
//     4 3 25 26 40
//
// Every problem gives one Status (Code::input) whose message says what and where ("line 7: ...").
// A model that passes the reader may still not be a triangulation of the image domain (overlaps,
// holes): reconstruct() checks that.
#pragma once
#include <string>
#include <vector>

#include "algorithms/model/model.h"
#include "kernel/status.h"

namespace erd {

struct ModelTopology;

enum class ModelFileKind { unknown, basic, erd, triangulation };

// The kind implied by a file name: ".model", ".erd", ".tri"; unknown otherwise (e.g. "-").
ModelFileKind model_kind_from_name(const std::string& name);

// Reads a .model or .erd text. With kind == unknown the content decides: a file that goes on
// after its faces (the wedge count) is an .erd, otherwise a .model. *topo (may be null) receives
// build_topology(*out), which the reader builds anyway, so reconstruct() need not build it again.
Status read_model(const std::string& text, ModelFileKind kind, Model* out, ModelTopology* topo = nullptr);

// Writes m as a .model (kind basic; every coordinate must be even) or an .erd (kind erd).
Status write_model(const Model& m, std::string* out);

// The -t triangulation: reads W, H, vertices, faces and constraints into *out (values and
// corner values left empty, kind basic); every constraint must be an edge of a face.
Status read_triangulation(const std::string& text, Model* out);
Status write_triangulation(const Model& m, std::string* out);

// The -p polylines (each a Polyline of algorithms/imaging/polylines.h). The reader takes
// coordinates of any image erd accepts (0 .. 2 kMaxImageSide - 2).
Status read_polylines(const std::string& text, std::vector<std::vector<LatticePoint>>* out);
void write_polylines(const std::vector<std::vector<LatticePoint>>& lines, std::string* out);

// For a consumer of gray models only: Code::input "a colour model (channels 3): WHAT handles gray
// models only" when m has more than one channel, success otherwise.
Status require_gray(const Model& m, const std::string& what);

// A value as the writers print it: an integer when integral, else the shortest decimal that
// reads back to the same double.
std::string format_value(double v);

// The header's GeoAsciiParams as one token: bytes outside '!'..'~', '%' and '#' as %XX.
std::string percent_encode(const std::string& s);

}  // namespace erd
