// The checks of a glTF file made before tinygltf parses it (gltf.cpp).
#include "io/gltf_precheck.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

namespace prox::io::gltf_detail {
namespace {

using Json = nlohmann::json;

constexpr int kMaxJsonDepth = 256;  // tinygltf parses extras recursively
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;

// Nesting depth outside strings; tinygltf recurses once per level.
int json_depth(const char* text, std::size_t size) {
  int depth = 0;
  int max_depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < size; ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      max_depth = std::max(max_depth, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return max_depth;
}

// Extensions that change nothing about triangle positions: a file requiring
// only these loads (its textures and materials are ignored anyway).
bool geometry_neutral(const std::string& extension) {
  return extension == "KHR_mesh_quantization" ||  // decoded by gltf.cpp
         extension == "KHR_texture_transform" || extension.rfind("KHR_materials_", 0) == 0 ||
         extension == "KHR_texture_basisu" || extension == "EXT_texture_webp" ||
         extension == "EXT_texture_avif";
}

// tinygltf's reading of an integer property (GetInt): a JSON integer, cast.
bool json_int(const Json& object, const char* key, int& value) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_integer()) return false;
  value = static_cast<int>(it->get<std::int64_t>());
  return true;
}
// tinygltf's reading of an unsigned property.
std::uint64_t json_unsigned(const Json& object, const char* key, std::uint64_t fallback) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number_unsigned() ? it->get<std::uint64_t>() : fallback;
}

}  // namespace

Status check_glb(const std::vector<unsigned char>& bytes, const std::string& name, GlbLayout& glb) {
  const auto error = [&](const std::string& message) -> Status {
    return {StatusCode::ParseError, name + ": " + message};
  };
  const std::size_t size = bytes.size();
  if (size < 20)
    return error("truncated GLB: " + std::to_string(size) + " bytes, a header and chunk need 20");
  const std::uint32_t version = read_u32le(&bytes[4]);
  if (version != 2)
    return {StatusCode::Unsupported,
            name + ": GLB container version " + std::to_string(version) + " (only version 2 is supported)"};
  const std::uint32_t length = read_u32le(&bytes[8]);
  if (length > size)
    return error("truncated GLB: the header declares " + std::to_string(length) + " bytes, the file has " +
                 std::to_string(size));
  if (length < 20) return error("GLB header declares a length of " + std::to_string(length) + " bytes");
  const std::uint64_t json_size = read_u32le(&bytes[12]);
  if (read_u32le(&bytes[16]) != kChunkJson) return error("the first GLB chunk is not JSON");
  if (json_size == 0 || 20 + json_size > length)
    return error("the GLB JSON chunk (" + std::to_string(json_size) +
                 " bytes) does not fit in the container (" + std::to_string(length) + " bytes)");
  const std::uint64_t bin_header = 20 + json_size;
  if (bin_header < length) {  // a second chunk follows
    if (bin_header + 8 > length) return error("truncated GLB: the second chunk header is cut off");
    const std::uint64_t bin_size = read_u32le(&bytes[bin_header]);
    if (read_u32le(&bytes[bin_header + 4]) != kChunkBin) return error("the second GLB chunk is not BIN");
    if (bin_header + 8 + bin_size > length)
      return error("truncated GLB: the BIN chunk declares " + std::to_string(bin_size) + " bytes, " +
                   std::to_string(length - bin_header - 8) + " are left");
  }
  glb.length = length;
  glb.json_offset = 20;
  glb.json_size = static_cast<std::size_t>(json_size);
  return Status::ok();
}

Status precheck_json(const char* text, std::size_t size, const std::string& name) {
  const auto error = [&](const std::string& message) -> Status {
    return {StatusCode::ParseError, name + ": " + message};
  };
  if (json_depth(text, size) > kMaxJsonDepth)
    return error("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  Json root;
  try {
    root = Json::parse(text, text + size);
  } catch (const Json::exception& e) {
    return error(std::string("invalid JSON: ") + e.what());
  }
  if (!root.is_object()) return error("the JSON root is not an object");

  const auto asset = root.find("asset");
  if (asset == root.end() || !asset->is_object() || !asset->contains("version") ||
      !(*asset)["version"].is_string())
    return error("no asset.version: not a glTF file");
  const std::string version = (*asset)["version"].get<std::string>();
  if (version.substr(0, version.find('.')) != "2")
    return {StatusCode::Unsupported, name + ": glTF version " + version + " (only 2.x is supported)"};

  const auto required = root.find("extensionsRequired");
  if (required != root.end()) {
    if (!required->is_array()) return error("extensionsRequired is not an array");
    std::string unsupported;
    for (const Json& extension : *required) {
      if (!extension.is_string()) return error("extensionsRequired holds a non-string");
      const std::string& e = extension.get_ref<const std::string&>();
      if (!geometry_neutral(e)) unsupported += (unsupported.empty() ? "" : ", ") + e;
    }
    if (!unsupported.empty())
      return {StatusCode::Unsupported,
              name + ": requires the glTF extension(s) " + unsupported + ", which Proxima cannot decode"};
  }

  // tinygltf hands an embedded image's bytes to the image callback as
  // &buffer.data[bufferView.byteOffset] without checking the view against the
  // buffer (it checks only the indices); a buffer's data always has its
  // byteLength, so check against that.
  const auto images = root.find("images");
  const auto views = root.find("bufferViews");
  const auto buffers = root.find("buffers");
  if (images != root.end() && images->is_array() && views != root.end() && views->is_array() &&
      buffers != root.end() && buffers->is_array()) {
    for (std::size_t i = 0; i < images->size(); ++i) {
      const Json& image = (*images)[i];
      int view_index = -1;
      if (!image.is_object() || !json_int(image, "bufferView", view_index) || view_index < 0 ||
          static_cast<std::size_t>(view_index) >= views->size())
        continue;  // tinygltf rejects or ignores these itself
      const Json& view = (*views)[static_cast<std::size_t>(view_index)];
      int buffer_index = -1;
      if (!view.is_object() || !json_int(view, "buffer", buffer_index) || buffer_index < 0 ||
          static_cast<std::size_t>(buffer_index) >= buffers->size() ||
          !(*buffers)[static_cast<std::size_t>(buffer_index)].is_object())
        continue;
      const std::uint64_t buffer_length =
          json_unsigned((*buffers)[static_cast<std::size_t>(buffer_index)], "byteLength", 0);
      const std::uint64_t offset = json_unsigned(view, "byteOffset", 0);
      const std::uint64_t length = json_unsigned(view, "byteLength", 0);
      if (offset >= buffer_length || length > buffer_length - offset)
        return error("image " + std::to_string(i) + ": bufferView " + std::to_string(view_index) +
                     " (byteOffset " + std::to_string(offset) + ", byteLength " + std::to_string(length) +
                     ") lies outside buffer " + std::to_string(buffer_index) + " (" +
                     std::to_string(buffer_length) + " bytes)");
    }
  }
  return Status::ok();
}

}  // namespace prox::io::gltf_detail
