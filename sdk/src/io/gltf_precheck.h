// The checks of a glTF file made before tinygltf parses it: the GLB
// container, and a first look at the JSON for what tinygltf would get wrong
// or reject with a less useful message. Private to gltf.cpp.
#pragma once

#include "common/status.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prox::io::gltf_detail {

inline std::uint32_t read_u32le(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

struct GlbLayout {
  std::size_t length = 0;  // the container's declared length (<= the file size)
  std::size_t json_offset = 0;
  std::size_t json_size = 0;
};

// The GLB container, checked completely (tinygltf 2.7 lets a BIN chunk
// header claim up to 8 bytes past the end). ParseError or Unsupported naming
// `name`.
Status check_glb(const std::vector<unsigned char>& bytes, const std::string& name, GlbLayout& glb);

// The JSON's nesting depth, asset.version, extensionsRequired, and embedded
// images' buffer views (tinygltf does not check them against the buffer).
Status precheck_json(const char* text, std::size_t size, const std::string& name);

}  // namespace prox::io::gltf_detail
