// glTF loading: every primitive mode, accessor encoding and node transform
// on small files written here.
#include "gltf_test_files.h"

namespace prox::io {
namespace {

using namespace gltf_test;

TEST(GltfModes, StripAlternatesItsWinding) {
  TempDir dir;
  const float zigzag[5][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}};
  Bytes bin = five_vertices(zigzag);
  put_all<std::uint8_t>(bin, {4, 3, 2, 1, 0});
  const std::string path = write_gltf(
      dir,
      one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":5},"
               "{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":5}]}]",
               "[" + view(0, 60) + "," + view(60, 5) + "]",
               "[" + accessor(0, 5, kFloat, "VEC3") + "," + accessor(1, 5, kUByte, "SCALAR") + "]"),
      bin);
  const std::vector<GltfMesh> m = load_ok(path);
  ASSERT_EQ(m.size(), 1u);
  // glTF: triangle i is (i, i+1, i+2) for even i, (i, i+2, i+1) for odd i.
  EXPECT_EQ(m[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4,     // non-indexed
                                                      4, 3, 2, 3, 1, 2, 2, 1, 0}));  // through indices 4..0
  for (std::size_t t = 0; t < 3; ++t) EXPECT_LT(winding(m[0], t), 0.0) << t;         // all clockwise
  for (std::size_t t = 3; t < 6; ++t) EXPECT_GT(winding(m[0], t), 0.0) << t;         // reversed order
}

TEST(GltfModes, FanAroundTheFirstVertex) {
  TempDir dir;
  const float fan[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}};
  const std::string path =
      write_gltf(dir,
                 one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":6}]}]",
                          "[" + view(0, 60) + "]", "[" + accessor(0, 5, kFloat, "VEC3") + "]"),
                 five_vertices(fan));
  const std::vector<GltfMesh> m = load_ok(path);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
  for (std::size_t t = 0; t < 3; ++t) EXPECT_GT(winding(m[0], t), 0.0) << t;
}

// Points and lines are skipped; a scene with nothing else is refused.
TEST(GltfModes, PointsAndLinesAreSkipped) {
  TempDir dir;
  const float xy[5][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 2}};
  std::string primitives;
  for (int mode : {0, 1, 2, 3})
    primitives += "{\"attributes\":{\"POSITION\":0},\"mode\":" + std::to_string(mode) + "},";
  const std::string path =
      write_gltf(dir,
                 one_node("[{\"primitives\":[" + primitives + "{\"attributes\":{\"POSITION\":1}}]}]",
                          "[" + view(0, 60) + "]",
                          "[" + accessor(0, 5, kFloat, "VEC3") + "," + accessor(0, 3, kFloat, "VEC3") + "]"),
                 five_vertices(xy));
  const std::vector<GltfMesh> m = load_ok(path);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(m[0].positions.size(), 9u);  // the points' accessor is not read

  const std::string points =
      write_gltf(dir,
                 one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":0}]}]",
                          "[" + view(0, 60) + "]", "[" + accessor(0, 5, kFloat, "VEC3") + "]"),
                 five_vertices(xy), "points");
  EXPECT_TRUE(contains(load_error(points, StatusCode::Unsupported), "no triangles"));
}

TEST(GltfModes, IndexComponentTypes) {
  TempDir dir;
  const float xy[5][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 2}};
  Bytes bin = five_vertices(xy);                    // 60 bytes
  put_all<std::uint8_t>(bin, {0, 1, 2, 2, 1, 4});   // 60..66
  pad4(bin);                                        // 68
  put_all<std::uint16_t>(bin, {0, 1, 2, 2, 1, 4});  // 68..80
  put_all<std::uint32_t>(bin, {0, 1, 2, 2, 1, 4});  // 80..104
  std::string primitives;
  for (int a : {1, 2, 3})
    primitives += std::string(a > 1 ? "," : "") +
                  "{\"attributes\":{\"POSITION\":0},\"indices\":" + std::to_string(a) + "}";
  const std::string path = write_gltf(
      dir,
      one_node("[{\"primitives\":[" + primitives + "]}]",
               "[" + view(0, 60) + "," + view(60, 6) + "," + view(68, 12) + "," + view(80, 24) + "]",
               "[" + accessor(0, 5, kFloat, "VEC3") + "," + accessor(1, 6, kUByte, "SCALAR") + "," +
                   accessor(2, 6, kUShort, "SCALAR") + "," + accessor(3, 6, kUInt, "SCALAR") + "]"),
      bin);
  const std::vector<GltfMesh> m = load_ok(path);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].positions.size(), 15u);  // one shared POSITION accessor, read once
  EXPECT_EQ(m[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 4, 0, 1, 2, 2, 1, 4, 0, 1, 2, 2, 1, 4}));
}

// KHR_mesh_quantization positions: normalized integers by the glTF formulas
// (signed: max(c / 127, -1), max(c / 32767, -1); unsigned: c / 255, c / 65535),
// unnormalized ones as they are. VEC3 of 8 or 16 bits is padded to a 4- or
// 8-byte stride.
TEST(GltfAccessors, QuantizedPositions) {
  TempDir dir;
  Bytes bin;
  std::string views, accessors, primitives;
  int next = 0;
  const auto add = [&](int type, bool normalized, std::size_t size, auto values) {
    const std::size_t offset = bin.size();
    for (const auto& v : values) {
      for (const auto c : v) put(bin, c);
      for (std::size_t pad = 3 * size; pad % 4 != 0; ++pad) bin.push_back(0xEE);
    }
    pad4(bin);
    const std::size_t stride = (3 * size + 3) / 4 * 4;
    const int index = next++;
    const std::string sep = index == 0 ? "" : ",";
    views += sep + view(offset, bin.size() - offset, stride);
    accessors += sep + accessor(index, 3, type, "VEC3", normalized ? ",\"normalized\":true" : "");
    primitives += sep + "{\"attributes\":{\"POSITION\":" + std::to_string(index) + "}}";
  };
  using B3 = std::array<std::int8_t, 3>;
  using UB3 = std::array<std::uint8_t, 3>;
  using S3 = std::array<std::int16_t, 3>;
  using US3 = std::array<std::uint16_t, 3>;
  add(kByte, true, 1, std::vector<B3>{{-128, 127, 0}, {64, -127, 1}, {0, 0, 0}});
  add(kUByte, true, 1, std::vector<UB3>{{255, 0, 51}, {0, 0, 0}, {1, 2, 3}});
  add(kShort, true, 2, std::vector<S3>{{-32768, 32767, 16384}, {0, 0, 0}, {-1, 1, 0}});
  add(kUShort, true, 2, std::vector<US3>{{65535, 0, 13107}, {0, 0, 0}, {1, 1, 1}});
  add(kByte, false, 1, std::vector<B3>{{-128, 127, 5}, {0, 0, 0}, {1, 1, 1}});
  add(kShort, false, 2, std::vector<S3>{{-5, 7, 300}, {0, 0, 0}, {1, 1, 1}});
  add(kUShort, false, 2, std::vector<US3>{{65535, 1, 2}, {0, 0, 0}, {1, 1, 1}});
  const std::string path = write_gltf(
      dir,
      "\"extensionsUsed\":[\"KHR_mesh_quantization\"],\"extensionsRequired\":[\"KHR_mesh_quantization\"]," +
          one_node("[{\"primitives\":[" + primitives + "]}]", "[" + views + "]", "[" + accessors + "]"),
      bin);
  const std::vector<GltfMesh> m = load_ok(path);
  ASSERT_EQ(m.size(), 1u);
  ASSERT_EQ(m[0].positions.size(), 7u * 9u);
  const auto vertex = [&](std::size_t primitive, std::size_t v) {
    const double* p = &m[0].positions[9 * primitive + 3 * v];
    return std::vector<double>{p[0], p[1], p[2]};
  };
  EXPECT_EQ(vertex(0, 0), (std::vector<double>{-1.0, 1.0, 0.0}));
  EXPECT_EQ(vertex(0, 1), (std::vector<double>{64 / 127.0, -1.0, 1 / 127.0}));
  EXPECT_EQ(vertex(1, 0), (std::vector<double>{1.0, 0.0, 51 / 255.0}));
  EXPECT_EQ(vertex(2, 0), (std::vector<double>{-1.0, 1.0, 16384 / 32767.0}));
  EXPECT_EQ(vertex(2, 2), (std::vector<double>{-1 / 32767.0, 1 / 32767.0, 0.0}));
  EXPECT_EQ(vertex(3, 0), (std::vector<double>{1.0, 0.0, 13107 / 65535.0}));
  EXPECT_EQ(vertex(4, 0), (std::vector<double>{-128.0, 127.0, 5.0}));
  EXPECT_EQ(vertex(5, 0), (std::vector<double>{-5.0, 7.0, 300.0}));
  EXPECT_EQ(vertex(6, 0), (std::vector<double>{65535.0, 1.0, 2.0}));
}

// KHR_mesh_quantization allows 8- and 16-bit positions, not 32-bit integers;
// normalized FLOAT does not exist.
TEST(GltfAccessors, InvalidPositionTypesAreRefused) {
  TempDir dir;
  Bytes bin;
  for (std::uint32_t i = 0; i < 9; ++i) put(bin, i);
  const std::string uint_path =
      write_gltf(dir,
                 one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]", "[" + view(0, 36) + "]",
                          "[" + accessor(0, 3, kUInt, "VEC3") + "]"),
                 bin, "uint");
  EXPECT_TRUE(contains(load_error(uint_path), "UNSIGNED_INT"));
  const std::string norm_path =
      write_gltf(dir,
                 one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]", "[" + view(0, 36) + "]",
                          "[" + accessor(0, 3, kFloat, "VEC3", ",\"normalized\":true") + "]"),
                 bin, "normfloat");
  EXPECT_TRUE(contains(load_error(norm_path), "normalized FLOAT"));
  const std::string vec2_path =
      write_gltf(dir,
                 one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]", "[" + view(0, 36) + "]",
                          "[" + accessor(0, 3, kFloat, "VEC2") + "]"),
                 bin, "vec2");
  EXPECT_TRUE(contains(load_error(vec2_path), "VEC2"));
}

// Interleaved position + normal (stride 24), a bufferView offset and accessor
// offsets; the last element needs only its own 12 bytes, not a whole stride.
TEST(GltfAccessors, StrideAndOffsets) {
  TempDir dir;
  Bytes bin;
  put_floats(bin, {99, 99});  // 8 bytes before the view
  put_floats(bin, {0, 0, 0, 10, 11, 12});
  put_floats(bin, {1, 0, 0, 13, 14, 15});
  put_floats(bin, {0, 1, 0, 16, 17, 18});  // the view ends after this normal
  const std::size_t length = 3 * 24;
  const std::string path = write_gltf(
      dir,
      one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}},{\"attributes\":{\"POSITION\":1}}]}]",
               "[" + view(8, length, 24) + "]",
               "[" + accessor(0, 3, kFloat, "VEC3") + "," +
                   accessor(0, 3, kFloat, "VEC3", ",\"byteOffset\":12") + "]"),
      bin);
  const std::vector<GltfMesh> m = load_ok(path);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 10, 11, 12, 13, 14, 15, 16, 17, 18}));
  EXPECT_EQ(m[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

// Sparse substitution on zeros (no bufferView), and malformed sparse parts.
TEST(GltfAccessors, SparseWithoutBufferView) {
  TempDir dir;
  // Two uint16 sparse indices (bytes 0..4), then their two float VEC3 values.
  const auto file = [&](std::uint16_t first, std::uint16_t second, const std::string& name) {
    Bytes bin;
    put(bin, first);
    put(bin, second);
    put_floats(bin, {1, 2, 3, 4, 5, 6});
    return write_gltf(
        dir,
        one_node(
            "[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]",
            "[" + view(0, 4) + "," + view(4, 24) + "]",
            "[" +
                accessor(-1, 3, kFloat, "VEC3",
                         ",\"sparse\":{\"count\":2,\"indices\":{\"bufferView\":0,\"componentType\":5123},"
                         "\"values\":{\"bufferView\":1}}") +
                "]"),
        bin, name);
  };
  const std::vector<GltfMesh> m = load_ok(file(0, 2, "ok"));
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].positions, (std::vector<double>{1, 2, 3, 0, 0, 0, 4, 5, 6}));
  EXPECT_TRUE(contains(load_error(file(2, 0, "decreasing")), "strictly increasing"));
  EXPECT_TRUE(contains(load_error(file(0, 3, "past")), "past the accessor"));
}

// Translation, rotation (x, y, z, w) and scale as T * R * S, under a parent
// matrix; a mesh used by two nodes appears once per node.
TEST(GltfNodes, TrsUnderAParentMatrixAndInstancing) {
  TempDir dir;
  Bytes bin;
  put_floats(bin, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  const auto file = [&](const std::string& rotation, const std::string& name) {
    return write_gltf(
        dir,
        "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":["
        "{\"name\":\"root\",\"children\":[1,2],\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 10,0,0,1]},"
        "{\"name\":\"turned\",\"mesh\":0,\"translation\":[1,2,3],\"rotation\":" +
            rotation +
            ",\"scale\":[2,1,1]},"
            "{\"mesh\":0}],"
            "\"meshes\":[{\"name\":\"tri\",\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
            "\"bufferViews\":[" +
            view(0, 36) + "],\"accessors\":[" + accessor(0, 3, kFloat, "VEC3") + "]",
        bin, name);
  };
  // 90 degrees about z: (x, y) -> (-y, x). (1,0,0) -> scale (2,0,0) -> rotate
  // (0,2,0) -> translate (1,4,3) -> parent (11,4,3).
  const std::vector<double> turned = {11, 4, 3, 10, 2, 3, 11, 2, 4};
  const std::vector<double> plain = {11, 0, 0, 10, 1, 0, 10, 0, 1};
  const double h = std::sqrt(0.5);
  for (const std::string& rotation : {"[0,0," + std::to_string(h) + "," + std::to_string(h) + "]",
                                      std::string("[0,0,0.7071067811865476,0.7071067811865476]"),
                                      std::string("[0,0,3,3]")}) {  // normalized before use
    SCOPED_TRACE(rotation);
    const std::vector<GltfMesh> nodes = load_ok(file(rotation, "nodes"), GltfSceneMode::PerNode);
    ASSERT_EQ(nodes.size(), 2u);
    EXPECT_EQ(nodes[0].name, "turned");
    EXPECT_EQ(nodes[1].name, "tri");  // unnamed node: the mesh's name
    for (std::size_t i = 0; i < 9; ++i) {
      EXPECT_NEAR(nodes[0].positions[i], turned[i], 1e-6) << i;
      EXPECT_NEAR(nodes[1].positions[i], plain[i], 0.0) << i;
    }
    const std::vector<GltfMesh> merged = load_ok(file(rotation, "merged"));
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_EQ(merged[0].name, "merged");
    EXPECT_EQ(merged[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  }
  const std::vector<GltfMesh> exact = load_ok(file("[0,0,0.7071067811865476,0.7071067811865476]", "exact"));
  for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(exact[0].positions[i], turned[i], 1e-15) << i;
}

// The default scene; scene 0 when the file names none; every root node when
// it has no scenes at all.
TEST(GltfNodes, SceneSelection) {
  TempDir dir;
  Bytes bin;
  put_floats(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  const std::string rest =
      ",\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"bufferViews\":[" + view(0, 36) +
      "],\"accessors\":[" + accessor(0, 3, kFloat, "VEC3") + "]";
  const std::string nodes =
      "\"nodes\":[{\"name\":\"a\",\"mesh\":0},{\"name\":\"b\",\"mesh\":0,\"children\":[2]},"
      "{\"name\":\"c\",\"mesh\":0}]";
  const auto names = [&](const std::string& scenes, const std::string& name) {
    std::vector<std::string> out;
    for (const GltfMesh& m :
         load_ok(write_gltf(dir, scenes + nodes + rest, bin, name), GltfSceneMode::PerNode))
      out.push_back(m.name);
    return out;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(names("\"scene\":1,\"scenes\":[{\"nodes\":[0]},{\"nodes\":[1]}],", "default"), (Names{"b", "c"}));
  EXPECT_EQ(names("\"scenes\":[{\"nodes\":[0]},{\"nodes\":[1]}],", "first"), (Names{"a"}));
  EXPECT_EQ(names("", "none"), (Names{"a", "b", "c"}));
  EXPECT_TRUE(contains(
      load_error(write_gltf(dir, "\"scene\":2,\"scenes\":[{\"nodes\":[0]}]," + nodes + rest, bin, "bad")),
      "the default scene 2 does not exist"));
}

// A buffer embedded as a base64 data URI instead of a .bin file.
TEST(GltfAccessors, EmbeddedDataUriBuffer) {
  TempDir dir;
  Bytes bin;
  put_floats(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string base64;
  for (std::size_t i = 0; i < bin.size(); i += 3) {  // 36 bytes: no padding needed
    const unsigned v = unsigned{bin[i]} << 16 | unsigned{bin[i + 1]} << 8 | unsigned{bin[i + 2]};
    for (int shift = 18; shift >= 0; shift -= 6) base64 += kAlphabet[(v >> shift) & 63];
  }
  const std::string json =
      "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,\"uri\":"
      "\"data:application/octet-stream;base64," +
      base64 + "\"}]," +
      one_node("[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]", "[" + view(0, 36) + "]",
               "[" + accessor(0, 3, kFloat, "VEC3") + "]") +
      "}";
  write_file(dir.file("embedded.gltf"), json);
  const std::vector<GltfMesh> m = load_ok(dir.file("embedded.gltf"));
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].positions, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
}

}  // namespace
}  // namespace prox::io
