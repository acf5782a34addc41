// Reading glTF accessors into doubles, shared by the geometry reader
// (gltf.cpp) and the skins, morph targets and animations reader
// (gltf_rig.cpp). Private to sdk/src/io; includes tinygltf's header without
// its implementation (compiled in gltf.cpp).
#pragma once

#include "common/status.h"

// The same configuration as gltf.cpp, which compiles the implementation.
#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#ifndef TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#endif
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prox::io::gltf_detail {

inline constexpr std::uint64_t kMaxU32 = 0xFFFFFFFFu;

const char* component_type_name(int type);
const char* type_name(int type);
// Bytes of one component; 0 for a type glTF 2.0 does not have.
std::size_t component_size(int type);
// One little-endian component; normalized integers map to [-1, 1] or [0, 1]
// by the glTF 2.0 formulas (signed: max(c / (2^(n-1) - 1), -1)).
double read_component(const unsigned char* p, int type, bool normalized);

// What an accessor is read for; each use allows the types the glTF 2.0
// specification (and KHR_mesh_quantization) allows for it.
enum class AccessorUse {
  Position,           // VEC3: FLOAT, or 8/16-bit integers (quantized)
  Index,              // SCALAR: UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT
  MorphPosition,      // VEC3: FLOAT, or 8/16-bit integers (quantized)
  Joints,             // VEC4: UNSIGNED_BYTE, UNSIGNED_SHORT, not normalized
  Weights,            // VEC4: FLOAT, normalized UNSIGNED_BYTE or UNSIGNED_SHORT
  InverseBindMatrix,  // MAT4: FLOAT
  Time,               // SCALAR: FLOAT (animation sampler input)
  Vec3Output,         // VEC3: FLOAT (translation, scale)
  RotationOutput,     // VEC4: FLOAT, normalized BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT
  WeightsOutput,      // SCALAR: FLOAT, normalized BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT
};
// Components per element for a use (3 for Position, 16 for a matrix, ...).
std::size_t components_of(AccessorUse use);

class AccessorReader {
 public:
  // `name` (the file) prefixes every message.
  AccessorReader(const tinygltf::Model& model, const std::string& name) : model_(model), name_(name) {}

  Status error(const std::string& message) const { return {StatusCode::ParseError, name_ + ": " + message}; }
  // A view's bytes, checked to lie inside its buffer.
  Status buffer_view(int index, const std::string& where, const unsigned char*& data,
                     std::size_t& length) const;
  // `count` elements of `element` bytes, `stride` apart from `offset`, must
  // lie within `length` bytes: offset + (count - 1) * stride + element.
  Status check_span(std::uint64_t offset, std::uint64_t count, std::uint64_t stride, std::uint64_t element,
                    std::uint64_t length, const std::string& what) const;
  // Accessor `index` as count * components_of(use) doubles: the base
  // bufferView (or zeros without one), then the sparse substitutions.
  // Messages read "<where> accessor <index>: ...".
  Status read(int index, const std::string& where, AccessorUse use, std::vector<double>& out) const;

 private:
  const tinygltf::Model& model_;
  const std::string& name_;
};

}  // namespace prox::io::gltf_detail
