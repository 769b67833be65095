// The model of an image with nodata (issue 47): the faces over nodata dropped from a model made on
// the triangulation of the whole rectangle (algorithms/imaging/valid_region.h has the region).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/model/model.h"

namespace erd {

struct DroppedFaces {
    std::size_t faces = 0;     // faces outside the valid region
    std::size_t vertices = 0;  // vertices that only such faces had
};

// Keeps the faces of *m whose inside lies in the valid region of the mask (valid[y*W + x] != 0,
// W x H = m's size), drops the others and the vertices no face keeps (the rest renumbered in
// order), and the constraints that are no longer between two faces. An ERD model's vertex values
// become the mean of the wedges its kept faces have, as the reader computes them from a file.
DroppedFaces drop_faces_over_nodata(const std::vector<std::uint8_t>& valid, Model* m);

}  // namespace erd
