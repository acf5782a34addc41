// A small skinned glTF written in memory (a .gltf whose buffer is a base64
// data: URI), with the joints and weights a test chooses: for the glTF MUST
// rules on skins, checked by the reader and through the C API.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

namespace gltf_rig_files {

inline std::string base64(const std::vector<unsigned char>& bytes) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned v = unsigned{bytes[i]} << 16;
    if (n > 1) v |= unsigned{bytes[i + 1]} << 8;
    if (n > 2) v |= unsigned{bytes[i + 2]};
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

enum class WeightType { Float = 5126, UByte = 5121, UShort = 5123 };

struct SkinnedTriangle {
  // Per vertex (3): four joints and four weights (raw integers for the
  // normalized types).
  std::vector<int> joints = {0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
  std::vector<double> weights = {1, 0, 0, 0, 0.5, 0.5, 0, 0, 1, 0, 0, 0};
  WeightType weight_type = WeightType::Float;
  bool second_joints_set = false;  // a JOINTS_1 (the JOINTS_0 accessor again) without WEIGHTS_1
  int joint_count = 2;             // the skin's joints (nodes 1 and 2)
  bool bare_primitive = false;     // a second primitive, its own POSITION accessor, no JOINTS_0

  // The .gltf text. Node 0 holds the mesh and skin; joint 0 is node 1 at the
  // origin, joint 1 is node 2, its child, at x = 1; inverse bind matrices are
  // identities.
  std::string json() const {
    std::vector<unsigned char> bin;
    const auto put = [&bin](const void* p, std::size_t n) {
      const auto* b = static_cast<const unsigned char*>(p);
      bin.insert(bin.end(), b, b + n);
    };
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    put(positions, sizeof positions);                                         // 36 bytes at 0
    for (const int j : joints) bin.push_back(static_cast<unsigned char>(j));  // 12 bytes at 36
    const std::size_t weights_at = bin.size();
    for (const double w : weights) {
      if (weight_type == WeightType::Float) {
        const float f = static_cast<float>(w);
        put(&f, 4);
      } else if (weight_type == WeightType::UByte) {
        bin.push_back(static_cast<unsigned char>(w));
      } else {
        const auto s = static_cast<std::uint16_t>(w);
        put(&s, 2);
      }
    }
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t ibm_at = bin.size();
    for (int j = 0; j < joint_count; ++j)
      for (int k = 0; k < 16; ++k) {
        const float f = k % 5 == 0 ? 1.0f : 0.0f;
        put(&f, 4);
      }
    const std::string type = std::to_string(static_cast<int>(weight_type));
    const std::string normalized = weight_type == WeightType::Float ? "" : ",\"normalized\":true";
    std::string joints_list;
    for (int j = 0; j < joint_count; ++j) joints_list += (j ? "," : "") + std::to_string(j == 0 ? 1 : 2);
    return "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) +
           ",\"uri\":\"data:application/octet-stream;base64," + base64(bin) +
           "\"}],\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
           "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":12},"
           "{\"buffer\":0,\"byteOffset\":" +
           std::to_string(weights_at) + ",\"byteLength\":" + std::to_string(ibm_at - weights_at) +
           "},{\"buffer\":0,\"byteOffset\":" + std::to_string(ibm_at) +
           ",\"byteLength\":" + std::to_string(bin.size() - ibm_at) +
           "}],\"accessors\":[{\"bufferView\":0,\"count\":3,\"componentType\":5126,\"type\":\"VEC3\"},"
           "{\"bufferView\":1,\"count\":3,\"componentType\":5121,\"type\":\"VEC4\"},"
           "{\"bufferView\":2,\"count\":3,\"componentType\":" +
           type + normalized +
           ",\"type\":\"VEC4\"},{\"bufferView\":3,\"count\":" + std::to_string(joint_count) +
           ",\"componentType\":5126,\"type\":\"MAT4\"}" +
           (bare_primitive ? ",{\"bufferView\":0,\"count\":3,\"componentType\":5126,\"type\":\"VEC3\"}"
                           : "") +
           "],\"meshes\":[{\"primitives\":[{\"attributes\":"
           "{\"POSITION\":0,\"JOINTS_0\":1,\"WEIGHTS_0\":2" +
           (second_joints_set ? ",\"JOINTS_1\":1" : "") + "}}" +
           (bare_primitive ? ",{\"attributes\":{\"POSITION\":4}}" : "") + "]}],\"skins\":[{\"joints\":[" +
           joints_list +
           "],\"inverseBindMatrices\":3}],\"nodes\":[{\"mesh\":0,\"skin\":0},{\"children\":[2]},"
           "{\"translation\":[1,0,0]}],\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}]}";
  }
};

// The unit right triangle in z = 0, one morph target lifting vertex 2 by 1
// in z, and one animation channel of node 0 with keyframes at `times`
// (values 0 and 1 for weights; (0,0,0) and (1,0,0) for translation).
struct MorphedTriangle {
  float times[2] = {0, 2};
  std::string path = "weights";
  bool node_matrix = false;  // node 0 has an identity matrix

  std::string json() const {
    std::vector<unsigned char> bin;
    const auto put = [&bin](std::initializer_list<float> values) {
      for (const float f : values) {
        unsigned char b[4];
        std::memcpy(b, &f, 4);
        bin.insert(bin.end(), b, b + 4);
      }
    };
    put({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, times[0], times[1]});
    const bool weights = path == "weights";
    if (weights)
      put({0, 1});
    else
      put({0, 0, 0, 1, 0, 0});
    return "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0" +
           std::string(node_matrix ? ",\"matrix\":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]" : "") +
           "}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1}]}]"
           "}],"
           "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"" +
           path + "\"}}],\"samplers\":[{\"input\":2,\"output\":3}]}],\"buffers\":[{\"byteLength\":" +
           std::to_string(bin.size()) + ",\"uri\":\"data:application/octet-stream;base64," + base64(bin) +
           "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,"
           "\"byteLength\":36},{\"buffer\":0,\"byteOffset\":72,\"byteLength\":8},{\"buffer\":0,"
           "\"byteOffset\":80,\"byteLength\":" +
           std::to_string(bin.size() - 80) +
           "}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
           "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
           "{\"bufferView\":2,\"componentType\":5126,\"count\":2,\"type\":\"SCALAR\"},"
           "{\"bufferView\":3,\"componentType\":5126,\"count\":2,\"type\":\"" +
           (weights ? "SCALAR" : "VEC3") + "\"}]}";
  }
};

}  // namespace gltf_rig_files
