// An independent glTF evaluator for the rig tests: reads the JSON with
// nlohmann and the buffers by hand (GLB chunks, base64 data: URIs), and
// computes every triangle of the default scene at an animation time with
// plain arrays (column-major 4x4 doubles), written apart from the SDK's
// mesh/rig.cpp and io/gltf_rig.cpp. Only what the shared skinned, morphed
// and animated samples use: TRIANGLES, indexed, FLOAT positions, byteStride,
// FLOAT or normalized integer weights, no sparse accessors.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace gltf_reference {

struct Document {
  nlohmann::json json;
  std::vector<std::vector<unsigned char>> buffers;
};

// Throws std::runtime_error on what it does not read.
Document open(const std::string& path);
Document parse(const std::vector<unsigned char>& bytes);

// Accessor `index` as doubles, `components` per element (normalized integers
// mapped to [0, 1] or [-1, 1]).
std::vector<double> accessor(const Document& doc, int index, int* components = nullptr);

// Triangles as 9 doubles (three corners), in scene order: depth first over
// the default scene's nodes, each mesh's primitives in order, each
// primitive's indices in order. `animation` -1: none (the rest pose).
// Float skin weights are divided by their sum (the SDK's documented choice).
std::vector<std::array<double, 9>> triangles(const Document& doc, int animation, double seconds);

// Spec formulas, for the interpolation checks.
std::array<double, 4> slerp(const std::array<double, 4>& a, const std::array<double, 4>& b, double t);

}  // namespace gltf_reference
