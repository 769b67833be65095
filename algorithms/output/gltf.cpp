#include "algorithms/output/gltf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "algorithms/output/little_endian.h"

namespace erd {

namespace {

// A JSON number that reads back as the same double (and as an integer when it is one).
std::string num(double v) {
    char buf[40];
    if (v == std::floor(v) && std::fabs(v) < 1e15) std::snprintf(buf, sizeof buf, "%.0f", v);
    else std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Our own description as a JSON string: any quote, backslash or control character (there are
// none in the texts export.cpp makes) becomes a space.
std::string quoted(std::string s) {
    for (char& c : s)
        if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) c = ' ';
    return "\"" + s + "\"";
}

}  // namespace

void write_glb(const GltfMesh& mesh, std::string* out) {
    const auto& pos = *mesh.positions;
    const auto& faces = *mesh.faces;
    const std::size_t n = pos.size();
    // BIN: positions (float VEC3), indices (uint32), colours (ubyte VEC4 is not needed: VEC3 with
    // each element 4-aligned, so padded to 4 bytes a vertex).
    std::string bin;
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
        const float v[3] = {float(pos[i][0]), float(pos[i][2]), float(-pos[i][1])};
        for (int k = 0; k < 3; ++k) {
            put_f32(&bin, v[k]);
            lo[k] = i == 0 ? v[k] : std::min(lo[k], v[k]);
            hi[k] = i == 0 ? v[k] : std::max(hi[k], v[k]);
        }
    }
    const std::size_t pos_bytes = bin.size();
    for (const auto& f : faces)
        for (std::uint32_t v : f) put_u32(&bin, v);
    const std::size_t idx_bytes = bin.size() - pos_bytes;
    const bool colour = mesh.colours && mesh.colours->size() == n;
    if (colour)
        for (const auto& c : *mesh.colours) {
            bin.push_back(char(c[0]));
            bin.push_back(char(c[1]));
            bin.push_back(char(c[2]));
            bin.push_back('\0');
        }
    const std::size_t col_bytes = bin.size() - pos_bytes - idx_bytes;
    while (bin.size() % 4) bin.push_back('\0');

    const auto bounds = [](const float* v) {
        return "[" + num(double(v[0])) + "," + num(double(v[1])) + "," + num(double(v[2])) + "]";
    };
    std::string j = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"erd\",\"extras\":{\"frame\":" + quoted(mesh.description) + "}},";
    j += "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],";
    j += "\"nodes\":[{\"mesh\":0";
    if (mesh.origin[0] != 0 || mesh.origin[1] != 0)
        j += ",\"translation\":[" + num(mesh.origin[0]) + ",0," + num(-mesh.origin[1]) + "]";
    j += "}],";
    j += "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[" + std::string(colour ? "1,1,1,1" : "0.8,0.78,0.72,1") +
         "],\"metallicFactor\":0,\"roughnessFactor\":0.9},\"doubleSided\":true}],";
    j += "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0" + std::string(colour ? ",\"COLOR_0\":2" : "") +
         "},\"indices\":1,\"material\":0,\"mode\":4}]}],";
    j += "\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) + "}],";
    j += "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" + std::to_string(pos_bytes) + ",\"target\":34962}";
    j += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(pos_bytes) + ",\"byteLength\":" + std::to_string(idx_bytes) + ",\"target\":34963}";
    if (colour)
        j += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(pos_bytes + idx_bytes) + ",\"byteLength\":" + std::to_string(col_bytes) +
             ",\"byteStride\":4,\"target\":34962}";
    j += "],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":" + std::to_string(n) + ",\"type\":\"VEC3\",\"min\":" + bounds(lo) +
         ",\"max\":" + bounds(hi) + "}";
    j += ",{\"bufferView\":1,\"componentType\":5125,\"count\":" + std::to_string(3 * faces.size()) + ",\"type\":\"SCALAR\"}";
    if (colour) j += ",{\"bufferView\":2,\"componentType\":5121,\"normalized\":true,\"count\":" + std::to_string(n) + ",\"type\":\"VEC3\"}";
    j += "]}";
    while (j.size() % 4) j.push_back(' ');

    out->clear();
    out->reserve(12 + 8 + j.size() + 8 + bin.size());
    out->append("glTF");
    put_u32(out, 2);
    put_u32(out, std::uint32_t(12 + 8 + j.size() + 8 + bin.size()));
    put_u32(out, std::uint32_t(j.size()));
    put_u32(out, 0x4E4F534Au);  // JSON
    out->append(j);
    put_u32(out, std::uint32_t(bin.size()));
    put_u32(out, 0x004E4942u);  // BIN
    out->append(bin);
}

}  // namespace erd
