// proxMesh_GetTriangles: the mesh handed back is the one given, after the
// documented welding and dropping, checked against an independent reading of
// the input (the triangles as position triples) and, for files, against the
// file parsed here and a closed cube's volume. proxWorld_LoadMeshFromMemory:
// the same meshes as from the files, and its misuse refused by name.
#include "expect.h"

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Triple = std::array<double, 9>;  // a triangle's three positions, in order

// The triangle starting at its smallest vertex, so the same triangle read
// from another vertex numbering compares equal (the winding is kept).
Triple canonical(Triple t) {
  auto key = [&](int k) { return std::array<double, 3>{t[3 * k], t[3 * k + 1], t[3 * k + 2]}; };
  int first = 0;
  for (int k = 1; k < 3; ++k)
    if (key(k) < key(first)) first = k;
  Triple out{};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) out[3 * k + c] = t[3 * ((first + k) % 3) + c];
  return out;
}

std::vector<Triple> triples(const std::vector<double>& positions, const std::vector<uint32_t>& indices,
                            bool drop_repeats) {
  std::vector<Triple> out;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    Triple tri{};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) tri[3 * k + c] = positions[3 * indices[t + k] + c];
    const bool repeats = std::equal(tri.begin(), tri.begin() + 3, tri.begin() + 3) ||
                         std::equal(tri.begin() + 3, tri.begin() + 6, tri.begin() + 6) ||
                         std::equal(tri.begin(), tri.begin() + 3, tri.begin() + 6);
    if (drop_repeats && repeats) continue;
    out.push_back(canonical(tri));
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Triangles {
  std::vector<double> positions;
  std::vector<uint32_t> indices;
};

Triangles get_triangles(proxMeshId mesh) {
  uint32_t vertices = 0, triangles = 0;
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, nullptr, 0, &vertices, nullptr, 0, &triangles),
               PROX_ERROR_CAPACITY, "capacities");
  Triangles out;
  out.positions.resize(3 * std::size_t{vertices});
  out.indices.resize(3 * std::size_t{triangles});
  uint32_t vertices2 = 0, triangles2 = 0;
  EXPECT_OK(proxMesh_GetTriangles(mesh, out.positions.data(), vertices, &vertices2, out.indices.data(),
                                  triangles, &triangles2));
  EXPECT_EQ(vertices2, vertices);
  EXPECT_EQ(triangles2, triangles);
  return out;
}

class MeshTriangles : public ::testing::Test {
 protected:
  void SetUp() override {
    const proxWorldDef def = proxDefaultWorldDef();
    ASSERT_OK(proxCreateWorld(&def, &world_));
  }
  void TearDown() override { EXPECT_OK(proxWorld_Destroy(world_)); }
  proxWorldId world_{};
};

// A unit cube as glTF files store it: 24 vertices (each face its own four),
// 12 triangles, plus one triangle that repeats a vertex (dropped) and one
// vertex no triangle uses.
void split_cube(std::vector<double>& positions, std::vector<uint32_t>& indices) {
  const int faces[6][4][3] = {
      {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}};
  for (const auto& face : faces) {
    const uint32_t base = static_cast<uint32_t>(positions.size() / 3);
    for (const auto& v : face)
      for (int c = 0; c < 3; ++c) positions.push_back(v[c]);
    for (const uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
  }
  for (const uint32_t i : {0u, 0u, 5u}) indices.push_back(i);  // repeats vertex 0
  for (const double x : {7.0, 7.0, 7.0}) positions.push_back(x);
}

TEST_F(MeshTriangles, GivesBackTheWeldedMeshOfCreateMesh) {
  std::vector<double> positions;
  std::vector<uint32_t> indices;
  split_cube(positions, indices);
  proxMeshDef def = proxDefaultMeshDef();
  def.positions = positions.data();
  def.vertexCount = static_cast<uint32_t>(positions.size() / 3);
  def.indices = indices.data();
  def.triangleCount = static_cast<uint32_t>(indices.size() / 3);
  proxMeshId mesh{};
  ASSERT_OK(proxWorld_CreateMesh(world_, &def, &mesh));

  const Triangles got = get_triangles(mesh);
  proxMeshInfo info{};
  ASSERT_OK(proxMesh_GetInfo(mesh, &info));
  EXPECT_EQ(got.indices.size(), 3u * info.triangleCount);
  EXPECT_EQ(got.positions.size(), 3u * info.vertexCount);
  EXPECT_EQ(got.indices.size(), 36u);  // the degenerate triangle dropped
  for (const uint32_t i : got.indices) EXPECT_LT(i, info.vertexCount);
  // Welded: no two vertices the triangles use share a position.
  std::vector<std::array<double, 3>> used;
  for (const uint32_t i : got.indices)
    used.push_back({got.positions[3 * i], got.positions[3 * i + 1], got.positions[3 * i + 2]});
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  EXPECT_EQ(used.size(), 8u);
  // The same triangles, with the same winding, as the input's.
  EXPECT_EQ(triples(got.positions, got.indices, false), triples(positions, indices, true));
}

TEST_F(MeshTriangles, RefusesWhatDoesNotFitAndWritesNothing) {
  const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const uint32_t indices[] = {0, 1, 2, 0, 3, 1};
  proxMeshDef def = proxDefaultMeshDef();
  def.positions = positions;
  def.vertexCount = 4;
  def.indices = indices;
  def.triangleCount = 2;
  proxMeshId mesh{};
  ASSERT_OK(proxWorld_CreateMesh(world_, &def, &mesh));

  std::vector<double> p(12, -1.0);
  std::vector<uint32_t> t(6, 99u);
  uint32_t nv = 0, nt = 0;
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, p.data(), 3, &nv, t.data(), 2, &nt), PROX_ERROR_CAPACITY,
               "4 vertices");
  EXPECT_EQ(nv, 4u);
  EXPECT_EQ(nt, 2u);
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, p.data(), 4, &nv, t.data(), 1, &nt), PROX_ERROR_CAPACITY,
               "2 triangles");
  EXPECT_TRUE(std::all_of(p.begin(), p.end(), [](double x) { return x == -1.0; }));
  EXPECT_TRUE(std::all_of(t.begin(), t.end(), [](uint32_t x) { return x == 99u; }));
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, nullptr, 4, &nv, t.data(), 2, &nt), PROX_ERROR_INVALID_ARGUMENT,
               "positions");
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, p.data(), 4, &nv, nullptr, 2, &nt), PROX_ERROR_INVALID_ARGUMENT,
               "indices");
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, p.data(), 4, nullptr, t.data(), 2, &nt),
               PROX_ERROR_INVALID_ARGUMENT, "vertexCount");
  EXPECT_FAILS(proxMesh_GetTriangles(mesh, p.data(), 4, &nv, t.data(), 2, nullptr),
               PROX_ERROR_INVALID_ARGUMENT, "triangleCount");
  // Room to spare is fine.
  std::vector<double> big(30);
  std::vector<uint32_t> bigt(30);
  ASSERT_OK(proxMesh_GetTriangles(mesh, big.data(), 10, &nv, bigt.data(), 10, &nt));
  EXPECT_EQ(std::vector<double>(big.begin(), big.begin() + 12),
            std::vector<double>(positions, positions + 12));

  proxMeshId stale = mesh;
  ASSERT_OK(proxMesh_Destroy(mesh));
  EXPECT_FAILS(proxMesh_GetTriangles(stale, big.data(), 10, &nv, bigt.data(), 10, &nt),
               PROX_ERROR_INVALID_HANDLE, "");
}

// The OBJ file parsed here (vertex lines and triangle faces only, as the
// bunny is written) against what the library read.
TEST_F(MeshTriangles, BunnyObjAsTheFileSaysAfterWelding) {
  const std::string path = std::string(PROX_SHARED_ASSETS_DIR) + "/bunny.obj";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::vector<double> positions;
  std::vector<uint32_t> indices;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      std::string x, y, z;
      s >> x >> y >> z;
      for (const std::string& c : {x, y, z}) positions.push_back(std::strtod(c.c_str(), nullptr));
    } else if (tag == "f") {
      std::string a;
      std::vector<uint32_t> face;
      while (s >> a) face.push_back(static_cast<uint32_t>(std::stoul(a.substr(0, a.find('/'))) - 1));
      ASSERT_EQ(face.size(), 3u) << line;
      indices.insert(indices.end(), face.begin(), face.end());
    }
  }
  proxMeshId mesh{};
  ASSERT_OK(proxWorld_LoadMesh(world_, path.c_str(), &mesh));
  const Triangles got = get_triangles(mesh);
  EXPECT_EQ(triples(got.positions, got.indices, false), triples(positions, indices, true));
}

std::vector<unsigned char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The mesh of a file's bytes is the file's, and the bytes are not kept:
// overwriting them afterwards changes nothing.
void expect_same_from_memory(proxWorldId world, const std::string& path, const std::string& name) {
  SCOPED_TRACE(name);
  proxMeshId from_file{}, from_memory{};
  ASSERT_OK(proxWorld_LoadMesh(world, path.c_str(), &from_file));
  std::vector<unsigned char> bytes = file_bytes(path);
  ASSERT_OK(proxWorld_LoadMeshFromMemory(world, bytes.data(), bytes.size(), name.c_str(), &from_memory));
  std::fill(bytes.begin(), bytes.end(), static_cast<unsigned char>(0));
  const Triangles a = get_triangles(from_file), b = get_triangles(from_memory);
  EXPECT_GT(a.indices.size(), 0u);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.indices, b.indices);
}

TEST_F(MeshTriangles, FromMemoryTheSameMeshAsFromTheFile) {
  const std::string assets = PROX_SHARED_ASSETS_DIR;
  expect_same_from_memory(world_, assets + "/bunny.obj", "bunny.obj");
  expect_same_from_memory(world_, assets + "/bunny.obj", "BUNNY.OBJ");  // the extension in any case
#if PROX_WITH_GLTF_TESTS
  expect_same_from_memory(world_, assets + "/gltf/Box.glb", "Box.glb");
  expect_same_from_memory(world_, assets + "/gltf/Duck.glb", "Duck.glb");
  // A GLB is known by its magic, whatever its name says.
  expect_same_from_memory(world_, assets + "/gltf/Box.glb", "asset-42");
#endif
}

TEST_F(MeshTriangles, FromMemoryRefusesMisuseByName) {
  const std::vector<unsigned char> obj = file_bytes(std::string(PROX_SHARED_ASSETS_DIR) + "/bunny.obj");
  proxMeshId mesh{};
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, obj.data(), obj.size(), "b.obj", nullptr),
               PROX_ERROR_INVALID_ARGUMENT, "mesh is NULL");
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(proxWorldId{}, obj.data(), obj.size(), "b.obj", &mesh),
               PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, obj.data(), obj.size(), nullptr, &mesh),
               PROX_ERROR_INVALID_ARGUMENT, "name is NULL");
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, nullptr, 10, "b.obj", &mesh), PROX_ERROR_INVALID_ARGUMENT,
               "data is NULL");
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, obj.data(), 0, "b.obj", &mesh),
               PROX_ERROR_INVALID_ARGUMENT, "b.obj: size is 0");
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, obj.data(), obj.size(), "b.stl", &mesh),
               PROX_ERROR_UNSUPPORTED, "b.stl: unsupported file type '.stl'");
  const std::string bad = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, bad.data(), bad.size(), "broken.obj", &mesh),
               PROX_ERROR_PARSE, "broken.obj:4");
  EXPECT_EQ(mesh.index1, 0u) << "no id with an error";
#if PROX_WITH_GLTF_TESTS
  // The GLB header (magic, version 2, a length of 255) and nothing after it.
  const std::string glb("glTF\x02\x00\x00\x00\xff\x00\x00\x00", 12);
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, glb.data(), glb.size(), "short.glb", &mesh),
               PROX_ERROR_PARSE, "short.glb");
  // A .gltf whose buffer is a file beside it: from memory, no file is read.
  const std::vector<unsigned char> gltf = file_bytes(
      std::string(PROX_SHARED_ASSETS_DIR) + "/gltf/TriangleWithoutIndices/TriangleWithoutIndices.gltf");
  EXPECT_FAILS(proxWorld_LoadMeshFromMemory(world_, gltf.data(), gltf.size(), "Triangle.gltf", &mesh),
               PROX_ERROR_FILE, "external buffer 'triangleWithoutIndices.bin' cannot be read");
  // ... and with that buffer embedded as a data: URI it loads: one triangle.
  const std::vector<unsigned char> bin = file_bytes(
      std::string(PROX_SHARED_ASSETS_DIR) + "/gltf/TriangleWithoutIndices/triangleWithoutIndices.bin");
  static const char* kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string encoded;
  for (std::size_t i = 0; i < bin.size(); i += 3) {
    const uint32_t n = (uint32_t{bin[i]} << 16) | (i + 1 < bin.size() ? uint32_t{bin[i + 1]} << 8 : 0u) |
                       (i + 2 < bin.size() ? uint32_t{bin[i + 2]} : 0u);
    for (int k = 0; k < 4; ++k)
      encoded += (i + static_cast<std::size_t>(k) > bin.size()) ? '=' : kBase64[(n >> (18 - 6 * k)) & 63];
  }
  std::string text(gltf.begin(), gltf.end());
  const std::string uri = "\"triangleWithoutIndices.bin\"";
  const std::size_t at = text.find(uri);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, uri.size(), "\"data:application/octet-stream;base64," + encoded + "\"");
  ASSERT_OK(proxWorld_LoadMeshFromMemory(world_, text.data(), text.size(), "Triangle.gltf", &mesh));
  proxMeshInfo info{};
  ASSERT_OK(proxMesh_GetInfo(mesh, &info));
  EXPECT_EQ(info.triangleCount, 1u);
#endif
}

#if PROX_WITH_GLTF_TESTS
// Khronos' Box.glb: a unit cube of 24 vertices under a node rotation. Welded
// to 8 corners at +-0.5, closed, wound outwards: its signed volume is +1.
TEST_F(MeshTriangles, BoxGlbIsAClosedUnitCubeWoundOutwards) {
  const std::string path = std::string(PROX_SHARED_ASSETS_DIR) + "/gltf/Box.glb";
  proxMeshId mesh{};
  ASSERT_OK(proxWorld_LoadMesh(world_, path.c_str(), &mesh));
  const Triangles got = get_triangles(mesh);
  ASSERT_EQ(got.positions.size(), 24u);
  ASSERT_EQ(got.indices.size(), 36u);
  for (const double x : got.positions) EXPECT_NEAR(std::abs(x), 0.5, 1e-6);
  double volume = 0;
  for (std::size_t t = 0; t < got.indices.size(); t += 3) {
    const double* a = &got.positions[3 * got.indices[t]];
    const double* b = &got.positions[3 * got.indices[t + 1]];
    const double* c = &got.positions[3 * got.indices[t + 2]];
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0])) /
              6.0;
  }
  EXPECT_NEAR(volume, 1.0, 1e-6);
}
#endif

}  // namespace
