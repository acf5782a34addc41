// glTF inputs at the edges, read from memory (io::load_gltf_bytes): invalid
// attributes Proxima does not read are warnings, not errors; node
// hierarchies 10^5 deep or cyclic; GLB chunk lengths of 2^32 - 1.
#include "io/gltf.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace prox::io {
namespace {

using Bytes = std::vector<unsigned char>;

// One triangle (0,0,0) (1,0,0) (0,1,0) as float32, then the indices 0 1 2
// as uint16: 42 bytes, base64 in a data URI.
const char* const kTriangleBuffer =
    "{\"byteLength\":42,\"uri\":\"data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA\"}";

// A file whose mesh 0 is that triangle with POSITION (accessor 0), indices
// (accessor 1) and the attributes in `attributes` (e.g. ",\"NORMAL\":2");
// `more_accessors` are appended after the first two.
std::string triangle_gltf(const std::string& nodes, const std::string& attributes = "",
                          const std::string& more_accessors = "", const std::string& scene = "[0]") {
  return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":" + scene +
         "}],\"nodes\":" + nodes + ",\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0" +
         attributes + "},\"indices\":1}]}],\"buffers\":[" + kTriangleBuffer +
         "],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":"
         "6}],"
         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
         "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}" +
         more_accessors + "]}";
}

Status load(const std::string& text, std::vector<GltfMesh>& out,
            std::vector<std::string>* warnings = nullptr) {
  return load_gltf_bytes(Bytes(text.begin(), text.end()), "test.gltf", GltfLoadOptions{}, out, warnings);
}

TEST(GltfWarnings, NormalPastItsBufferViewLoadsWithAWarning) {
  // NORMAL: 30 VEC3 floats (360 bytes) in the 36-byte view.
  const std::string text =
      triangle_gltf("[{\"mesh\":0}]", ",\"NORMAL\":2",
                    ",{\"bufferView\":0,\"componentType\":5126,\"count\":30,\"type\":\"VEC3\"}");
  std::vector<GltfMesh> meshes;
  std::vector<std::string> warnings;
  const Status status = load(text, meshes, &warnings);
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_EQ(meshes.size(), 1u);
  EXPECT_EQ(meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("test.gltf: mesh 0 primitive 0: NORMAL accessor 2"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("run past the end of the bufferView (36 bytes)"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("skipped"), std::string::npos) << warnings[0];
  // Without a warnings list it loads the same, silently.
  EXPECT_TRUE(load(text, meshes).is_ok());
}

TEST(GltfWarnings, EachInvalidAttributeOnceAndValidOnesNever) {
  // TEXCOORD_0 valid (3 VEC2 floats = 24 bytes), NORMAL and TANGENT sharing
  // an accessor whose view does not exist, COLOR_0 an accessor that does not
  // exist, JOINTS_0 of an invalid component type: three warnings.
  const std::string text =
      triangle_gltf("[{\"mesh\":0},{\"mesh\":0}]",
                    ",\"TEXCOORD_0\":2,\"NORMAL\":3,\"TANGENT\":3,\"COLOR_0\":9,\"JOINTS_0\":4",
                    ",{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC2\"}"
                    ",{\"bufferView\":7,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}"
                    ",{\"bufferView\":0,\"componentType\":5130,\"count\":3,\"type\":\"VEC4\"}",
                    "[0,1]");
  std::vector<GltfMesh> meshes;
  std::vector<std::string> warnings;
  const Status status = load(text, meshes, &warnings);
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_EQ(warnings.size(), 3u);
  std::string all;
  for (const std::string& w : warnings) all += w + "\n";
  EXPECT_NE(all.find("COLOR_0 accessor 9 does not exist"), std::string::npos) << all;
  EXPECT_NE(all.find("JOINTS_0 accessor 4"), std::string::npos) << all;
  EXPECT_NE(all.find("bufferView 7 does not exist"), std::string::npos) << all;
  EXPECT_EQ(all.find("TEXCOORD_0"), std::string::npos) << all;
}

TEST(GltfWarnings, AnErrorLeavesNoWarnings) {
  // The warning is found, then the indices accessor fails: an error, and the
  // warnings list is emptied with the meshes.
  std::string text =
      triangle_gltf("[{\"mesh\":0}]", ",\"NORMAL\":2",
                    ",{\"bufferView\":0,\"componentType\":5126,\"count\":30,\"type\":\"VEC3\"}");
  text.replace(text.find("\"count\":3,\"type\":\"SCALAR\""), 9, "\"count\":4");
  std::vector<GltfMesh> meshes;
  std::vector<std::string> warnings{"stale"};
  EXPECT_FALSE(load(text, meshes, &warnings).is_ok());
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(meshes.empty());
}

// node i has child i + 1 and a translation of 1 along x; the last one holds
// the mesh.
std::string chain(int n, bool cycle) {
  std::string nodes = "[";
  for (int i = 0; i < n; ++i) {
    if (i > 0) nodes += ",";
    const bool last = i == n - 1;
    nodes += "{\"translation\":[1,0,0]";
    if (last) nodes += ",\"mesh\":0";
    if (!last || cycle) nodes += ",\"children\":[" + std::to_string(last ? 0 : i + 1) + "]";
    nodes += "}";
  }
  return nodes + "]";
}

TEST(GltfNodesAtScale, HierarchyOneHundredThousandDeep) {
  constexpr int kDepth = 100000;
  std::vector<GltfMesh> meshes;
  const auto start = std::chrono::steady_clock::now();
  const Status status = load(triangle_gltf(chain(kDepth, false)), meshes);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_EQ(meshes.size(), 1u);
  // Every translation applied: the first vertex moved 10^5 along x.
  EXPECT_EQ(meshes[0].positions[0], static_cast<double>(kDepth));
  EXPECT_EQ(meshes[0].positions[3], static_cast<double>(kDepth) + 1.0);
  // Iterative traversal, linear in the nodes: far below a second here.
  EXPECT_LT(seconds, 30.0);
}

TEST(GltfNodesAtScale, CyclesAndSharedChildrenAreRefused) {
  std::vector<GltfMesh> meshes;
  // A ring of 10^5 nodes, the last pointing back at the first.
  Status status = load(triangle_gltf(chain(100000, true)), meshes);
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_NE(status.message().find("node 0 is reached twice"), std::string::npos) << status.message();
  EXPECT_NE(status.message().find("cycle"), std::string::npos) << status.message();
  // A node that is its own child.
  status = load(triangle_gltf("[{\"mesh\":0,\"children\":[0]}]"), meshes);
  EXPECT_NE(status.message().find("node 0 is reached twice"), std::string::npos) << status.message();
  // Two parents of one node.
  status = load(triangle_gltf("[{\"children\":[1,2]},{\"children\":[2]},{\"mesh\":0}]"), meshes);
  EXPECT_NE(status.message().find("node 2 is reached twice"), std::string::npos) << status.message();
  EXPECT_TRUE(meshes.empty());
}

// A GLB of `json` and a BIN chunk of `bin` bytes.
Bytes glb(std::string json, std::size_t bin) {
  while (json.size() % 4 != 0) json += ' ';
  const std::uint32_t length = static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin);
  Bytes out(length, 0);
  const auto put = [&](std::size_t at, std::uint32_t v) { std::memcpy(&out[at], &v, 4); };
  std::memcpy(out.data(), "glTF", 4);
  put(4, 2);
  put(8, length);
  put(12, static_cast<std::uint32_t>(json.size()));
  put(16, 0x4E4F534A);
  std::memcpy(&out[20], json.data(), json.size());
  put(20 + json.size(), static_cast<std::uint32_t>(bin));
  put(24 + json.size(), 0x004E4942);
  return out;
}

TEST(GlbAtScale, ChunkLengthsOfTwoToTheThirtyTwoMinusOne) {
  const std::string json = "{\"asset\":{\"version\":\"2.0\"}}";
  const std::size_t bin_header = 20 + (json.size() + 3) / 4 * 4;
  const auto with = [&](std::size_t at) {
    Bytes bytes = glb(json, 16);
    const std::uint32_t huge = 0xFFFFFFFFu;
    std::memcpy(&bytes[at], &huge, 4);
    std::vector<GltfMesh> meshes;
    return load_gltf_bytes(bytes, "huge.glb", GltfLoadOptions{}, meshes);
  };
  Status status = with(12);  // the JSON chunk
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_NE(status.message().find("JSON chunk (4294967295 bytes) does not fit"), std::string::npos)
      << status.message();
  status = with(bin_header);  // the BIN chunk
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_NE(status.message().find("BIN chunk declares 4294967295 bytes"), std::string::npos)
      << status.message();
  status = with(8);  // the container
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_NE(status.message().find("declares 4294967295 bytes"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace prox::io
