// glTF loading: truncated, corrupted and inconsistent files, which must
// give an error that names the file, or a well-formed scene.
#include "gltf_test_files.h"

namespace prox::io {
namespace {

using namespace gltf_test;

// ---------------------------------------------------------------------------
// Bad files: each gives an error that names the file and the problem.

// A one-triangle file with `view_length` bytes of view on a 36-byte buffer.
std::string triangle_file(const TempDir& dir, const std::string& name, const std::string& views,
                          const std::string& accessors, const Bytes& bin,
                          const std::string& primitive_extra = "",
                          const std::string& nodes = "[{\"mesh\":0}]") {
  return write_gltf(dir,
                    "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":" + nodes +
                        ",\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}" + primitive_extra +
                        "}]}],\"bufferViews\":" + views + ",\"accessors\":" + accessors,
                    bin, name);
}

Bytes triangle_bin() {
  Bytes bin;
  put_floats(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  return bin;
}

TEST(GltfErrors, BufferViewPastTheBufferEnd) {
  TempDir dir;
  const std::string path = triangle_file(dir, "view", "[" + view(0, 48) + "]",
                                         "[" + accessor(0, 3, kFloat, "VEC3") + "]", triangle_bin());
  const std::string message = load_error(path);
  EXPECT_TRUE(contains(message, "bufferView 0")) << message;
  EXPECT_TRUE(contains(message, "runs past the end of buffer 0 (36 bytes)")) << message;
}

TEST(GltfErrors, AccessorCountPastTheView) {
  TempDir dir;
  const std::string path = triangle_file(dir, "count", "[" + view(0, 36) + "]",
                                         "[" + accessor(0, 4, kFloat, "VEC3") + "]", triangle_bin());
  const std::string message = load_error(path);
  EXPECT_TRUE(contains(message, "mesh 0 primitive 0: POSITION accessor 0")) << message;
  EXPECT_TRUE(contains(message, "run past the end of the bufferView")) << message;

  const std::string offset =
      triangle_file(dir, "offset", "[" + view(0, 36) + "]",
                    "[" + accessor(0, 3, kFloat, "VEC3", ",\"byteOffset\":4") + "]", triangle_bin());
  EXPECT_TRUE(contains(load_error(offset), "run past the end of the bufferView"));
}

TEST(GltfErrors, IndexOutOfRange) {
  TempDir dir;
  Bytes bin = triangle_bin();
  put_all<std::uint16_t>(bin, {0, 1, 3});
  pad4(bin);
  const std::string path =
      triangle_file(dir, "index", "[" + view(0, 36) + "," + view(36, 6) + "]",
                    "[" + accessor(0, 3, kFloat, "VEC3") + "," + accessor(1, 3, kUShort, "SCALAR") + "]", bin,
                    ",\"indices\":1");
  const std::string message = load_error(path);
  EXPECT_TRUE(contains(message, "index 3 (entry 2) is out of range")) << message;
  EXPECT_TRUE(contains(message, "3 vertices")) << message;
}

TEST(GltfErrors, NonFinitePositions) {
  TempDir dir;
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    Bytes bin;
    put_floats(bin, {0, 0, 0, 1, 0, 0, 0, bad, 0});
    const std::string path =
        triangle_file(dir, "nan", "[" + view(0, 36) + "]", "[" + accessor(0, 3, kFloat, "VEC3") + "]", bin);
    const std::string message = load_error(path);
    EXPECT_TRUE(contains(message, "vertex 2 has a non-finite coordinate")) << message;
  }
  // Finite in the file, infinite in the world.
  const std::string huge = triangle_file(dir, "huge", "[" + view(0, 36) + "]",
                                         "[" + accessor(0, 3, kFloat, "VEC3") + "]", triangle_bin(), "",
                                         "[{\"mesh\":0,\"scale\":[1e308,1e308,1e308],\"children\":[1]},"
                                         "{\"mesh\":0,\"scale\":[1e308,1e308,1e308]}]");
  EXPECT_TRUE(contains(load_error(huge), "overflows"));
}

TEST(GltfErrors, TrianglesNotAMultipleOfThree) {
  TempDir dir;
  Bytes bin = triangle_bin();
  put_all<std::uint16_t>(bin, {0, 1, 2, 0});
  const std::string path =
      triangle_file(dir, "four", "[" + view(0, 36) + "," + view(36, 8) + "]",
                    "[" + accessor(0, 3, kFloat, "VEC3") + "," + accessor(1, 4, kUShort, "SCALAR") + "]", bin,
                    ",\"indices\":1");
  EXPECT_TRUE(contains(load_error(path), "4 vertices for TRIANGLES"));
}

TEST(GltfErrors, BadNodes) {
  TempDir dir;
  const std::string views = "[" + view(0, 36) + "]";
  const std::string accessors = "[" + accessor(0, 3, kFloat, "VEC3") + "]";
  const auto nodes = [&](const std::string& name, const std::string& json) {
    return load_error(triangle_file(dir, name, views, accessors, triangle_bin(), "", json));
  };
  EXPECT_TRUE(
      contains(nodes("cycle", "[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}]"), "reached twice"));
  EXPECT_TRUE(contains(nodes("child", "[{\"mesh\":0,\"children\":[7]}]"), "node 7 does not exist"));
  EXPECT_TRUE(contains(nodes("mesh", "[{\"mesh\":5}]"), "mesh 5"));
  EXPECT_TRUE(contains(nodes("affine", "[{\"mesh\":0,\"matrix\":[1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]"),
                       "not affine"));
  EXPECT_TRUE(contains(nodes("short", "[{\"mesh\":0,\"matrix\":[1,0,0,0]}]"), "16 are needed"));
  EXPECT_TRUE(contains(nodes("quat", "[{\"mesh\":0,\"rotation\":[0,0,0,0]}]"), "zero or non-finite length"));
  EXPECT_TRUE(contains(nodes("trs", "[{\"mesh\":0,\"translation\":[1,2]}]"), "translation has 2 values"));
}

// tinygltf hands an embedded image's bytes to the (no-op) image callback
// without checking its bufferView against the buffer: checked beforehand.
TEST(GltfErrors, ImageBufferViewPastTheBuffer) {
  TempDir dir;
  const std::string body =
      one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]",
               "[" + view(0, 36) + "," + view(30, 100) + "]", "[" + accessor(0, 3, kFloat, "VEC3") + "]");
  const std::string bad = write_gltf(
      dir, "\"images\":[{\"bufferView\":1,\"mimeType\":\"image/png\"}]," + body, triangle_bin(), "bad");
  EXPECT_TRUE(contains(load_error(bad),
                       "image 0: bufferView 1 (byteOffset 30, byteLength 100) lies outside buffer 0"));
  // An image inside the buffer is accepted without being decoded.
  const std::string good = write_gltf(
      dir,
      "\"images\":[{\"bufferView\":1,\"mimeType\":\"image/png\"}]," +
          one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]",
                   "[" + view(0, 36) + "," + view(4, 8) + "]", "[" + accessor(0, 3, kFloat, "VEC3") + "]"),
      triangle_bin(), "good");
  load_ok(good);
}

TEST(GltfErrors, RequiredExtensions) {
  TempDir dir;
  const std::string body = one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]",
                                    "[" + view(0, 36) + "]", "[" + accessor(0, 3, kFloat, "VEC3") + "]");
  const auto file = [&](const std::string& required, const std::string& name) {
    return write_gltf(dir, "\"extensionsRequired\":[" + required + "]," + body, triangle_bin(), name);
  };
  load_ok(file("\"KHR_mesh_quantization\",\"KHR_texture_transform\",\"KHR_materials_variants\"", "neutral"));
  const std::string message = load_error(
      file("\"KHR_texture_transform\",\"EXT_meshopt_compression\"", "meshopt"), StatusCode::Unsupported);
  EXPECT_TRUE(contains(message, "EXT_meshopt_compression")) << message;
  EXPECT_FALSE(contains(message, "KHR_texture_transform")) << message;
}

TEST(GltfErrors, FilesThatCannotBeRead) {
  TempDir dir;
  EXPECT_TRUE(contains(load_error(dir.file("absent.glb"), StatusCode::IoError), "cannot open"));
  const std::string path = triangle_file(dir, "nobin", "[" + view(0, 36) + "]",
                                         "[" + accessor(0, 3, kFloat, "VEC3") + "]", triangle_bin());
  fs::remove(dir.file("nobin.bin"));
  const std::string message = load_error(path, StatusCode::IoError);
  EXPECT_TRUE(contains(message, "nobin.bin")) << message;
  // A .bin of the wrong size is malformed, not unreadable.
  triangle_file(dir, "short", "[" + view(0, 36) + "]", "[" + accessor(0, 3, kFloat, "VEC3") + "]",
                triangle_bin());
  write_file(dir.file("short.bin"), Bytes(20, 0));
  load_error(dir.file("short.gltf"));
}

TEST(GltfErrors, NotGltf) {
  TempDir dir;
  write_file(dir.file("text.gltf"), std::string("{\"asset\":{\"version\":\"2.0\"},\"meshes\":[{]}"));
  EXPECT_TRUE(contains(load_error(dir.file("text.gltf")), "invalid JSON"));
  write_file(dir.file("old.gltf"), std::string("{\"asset\":{\"version\":\"1.0\"}}"));
  EXPECT_TRUE(contains(load_error(dir.file("old.gltf"), StatusCode::Unsupported), "version 1.0"));
  write_file(dir.file("noasset.gltf"), std::string("{\"meshes\":[]}"));
  EXPECT_TRUE(contains(load_error(dir.file("noasset.gltf")), "asset.version"));
  write_file(dir.file("deep.gltf"), std::string(100000, '['));
  EXPECT_TRUE(contains(load_error(dir.file("deep.gltf")), "nested deeper"));
  write_file(dir.file("obj.glb"), std::string("v 0 0 0\n"));
  EXPECT_TRUE(contains(load_error(dir.file("obj.glb")), "magic"));
}

// ---------------------------------------------------------------------------
// Corrupted copies of Box.glb: truncated anywhere, bytes flipped anywhere in
// its JSON and BIN chunks. Every result is an error or a well-formed scene.

class BoxGlb : public ::testing::Test {
 protected:
  void SetUp() override {
    original_ = read_bytes(asset("gltf/Box.glb"));
    ASSERT_EQ(original_.size(), 1664u) << "missing or changed shared asset gltf/Box.glb";
    std::memcpy(&json_size_, &original_[12], 4);
    ASSERT_EQ(json_size_, 988u);
  }
  // Loads `bytes` as a .glb; returns the status, checking the scene if any.
  Status load(const Bytes& bytes, const std::string& what) {
    write_file(path_, bytes);
    std::vector<GltfMesh> out;
    const Status status = load_gltf(path_, {}, out);
    if (status.is_ok()) {
      expect_well_formed(out, what);
      EXPECT_GT(triangles(out), 0u) << what;
    } else {
      EXPECT_TRUE(out.empty()) << what;
      EXPECT_TRUE(contains(status.message(), path_)) << what << ": " << status.message();
    }
    return status;
  }

  TempDir dir_;
  const std::string path_ = dir_.file("box.glb");
  Bytes original_;
  std::uint32_t json_size_ = 0;
};

TEST_F(BoxGlb, IntactLoads) { EXPECT_TRUE(load(original_, "intact").is_ok()); }

TEST_F(BoxGlb, EveryTruncationIsAnError) {
  for (std::size_t length = 0; length < original_.size(); ++length) {
    const Bytes cut(original_.begin(), original_.begin() + static_cast<std::ptrdiff_t>(length));
    const Status status = load(cut, "truncated to " + std::to_string(length));
    EXPECT_EQ(status.code(), StatusCode::ParseError) << length << ": " << status.message();
  }
}

TEST_F(BoxGlb, FlippedJsonBytesNeverCrash) {
  std::size_t errors = 0;
  std::size_t tried = 0;
  for (std::size_t i = 20; i < 20 + json_size_; ++i)
    for (const unsigned char mask : std::initializer_list<unsigned char>{0x01, 0x20, 0x80}) {
      Bytes bytes = original_;
      bytes[i] ^= mask;
      ++tried;
      if (!load(bytes, "byte " + std::to_string(i) + " ^ " + std::to_string(mask)).is_ok()) ++errors;
    }
  EXPECT_GT(errors, tried / 4);  // most flips break the JSON
}

TEST_F(BoxGlb, FlippedBinBytesNeverCrash) {
  std::size_t errors = 0;
  for (std::size_t i = 28 + json_size_; i < original_.size(); ++i) {
    Bytes bytes = original_;
    bytes[i] ^= 0xFF;
    if (!load(bytes, "byte " + std::to_string(i)).is_ok()) ++errors;
  }
  EXPECT_GT(errors, 0u);  // at least the flipped exponents and index high bytes
}

TEST_F(BoxGlb, ContainerLies) {
  const auto with_u32 = [&](std::size_t at, std::uint32_t value) {
    Bytes bytes = original_;
    std::memcpy(&bytes[at], &value, 4);
    return bytes;
  };
  EXPECT_EQ(load(with_u32(4, 1), "version 1").code(), StatusCode::Unsupported);
  EXPECT_EQ(load(with_u32(8, 5000), "length past the end").code(), StatusCode::ParseError);
  EXPECT_EQ(load(with_u32(12, 5000), "JSON chunk past the end").code(), StatusCode::ParseError);
  const std::size_t bin = 20 + json_size_;
  for (const std::uint32_t lie : {652u, 656u, 1000u, 0xFFFFFFFCu})  // 648 is true
    EXPECT_EQ(load(with_u32(bin, lie), "BIN chunk " + std::to_string(lie)).code(), StatusCode::ParseError);
  EXPECT_EQ(load(with_u32(bin + 4, 0x12345678), "BIN chunk type").code(), StatusCode::ParseError);
  // Trailing bytes after the declared length are ignored.
  Bytes longer = original_;
  longer.resize(longer.size() + 16, 0xAB);
  EXPECT_TRUE(load(longer, "trailing bytes").is_ok());
}

}  // namespace
}  // namespace prox::io
