// glTF 2.0 binary (.glb) of a mesh (issue 47), the format three.js, Cesium, Blender, Unity and
// Unreal read: the GLB container (header, JSON chunk, BIN chunk) around one node, one mesh of one
// indexed triangle list. export.h says which frame and which vertices.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace erd {

struct GltfMesh {
    // x, y, z with z up (as export.h's frame): written with y up (glTF x = x, y = z, z = -y).
    const std::vector<std::array<double, 3>>* positions = nullptr;
    // Corners counter-clockwise seen from +z (they stay counter-clockwise from glTF's +y).
    const std::vector<std::array<std::uint32_t, 3>>* faces = nullptr;
    const std::vector<std::array<std::uint8_t, 3>>* colours = nullptr;  // per position, or null
    std::array<double, 2> origin = {0, 0};  // added back by the node's translation (x, y)
    std::string description;                // asset.extras.frame
};

// The .glb bytes into *out.
void write_glb(const GltfMesh& mesh, std::string* out);

}  // namespace erd
