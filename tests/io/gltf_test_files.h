// Helpers of the glTF reader's tests: the shared assets, bounds and
// well-formedness checks, and small glTF files written byte by byte.
#pragma once

#include "io/gltf.h"
#include "io/obj.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace prox::io::gltf_test {

namespace fs = std::filesystem;

inline std::string asset(const std::string& relative) {
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + relative;
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

struct Bounds {
  double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  std::numeric_limits<double>::infinity()};
  double hi[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  double size(int axis) const { return hi[axis] - lo[axis]; }
  void add(const double* p) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
};

// Over the vertices the triangles use.
inline Bounds bounds(const std::vector<GltfMesh>& meshes) {
  Bounds b;
  for (const GltfMesh& m : meshes)
    for (const std::uint32_t i : m.indices) b.add(&m.positions[3 * std::size_t{i}]);
  return b;
}
inline Bounds bounds(const GltfMesh& mesh) { return bounds(std::vector<GltfMesh>{mesh}); }

inline std::size_t triangles(const std::vector<GltfMesh>& meshes) {
  std::size_t n = 0;
  for (const GltfMesh& m : meshes) n += m.indices.size() / 3;
  return n;
}

// Every soup well formed: whole triangles, indices in range, finite positions.
inline void expect_well_formed(const std::vector<GltfMesh>& meshes, const std::string& what) {
  for (const GltfMesh& m : meshes) {
    EXPECT_EQ(m.positions.size() % 3, 0u) << what;
    EXPECT_EQ(m.indices.size() % 3, 0u) << what;
    const std::size_t n = m.positions.size() / 3;
    for (const std::uint32_t i : m.indices) ASSERT_LT(i, n) << what;
    for (const double x : m.positions) ASSERT_TRUE(std::isfinite(x)) << what;
  }
}

inline void expect_bounds(const Bounds& b, const double (&lo)[3], const double (&hi)[3], double tolerance,
                          const std::string& what) {
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(b.lo[a], lo[a], tolerance) << what << " axis " << a;
    EXPECT_NEAR(b.hi[a], hi[a], tolerance) << what << " axis " << a;
  }
}

inline void expect_size(const Bounds& b, double x, double y, double z, double tolerance,
                        const std::string& what) {
  EXPECT_NEAR(b.size(0), x, tolerance) << what;
  EXPECT_NEAR(b.size(1), y, tolerance) << what;
  EXPECT_NEAR(b.size(2), z, tolerance) << what;
}

// Loads a shared asset; a missing assets folder or file fails the test.
inline std::vector<GltfMesh> load_asset(const std::string& relative,
                                        GltfSceneMode mode = GltfSceneMode::Merged,
                                        double* seconds = nullptr) {
  const std::string path = asset(relative);
  EXPECT_TRUE(fs::exists(path)) << "missing shared asset " << path
                                << ": the shared assets are missing: put them in ../shared/assets beside the "
                                   "repository or configure with -DPROX_SHARED_ASSETS_DIR";
  std::vector<GltfMesh> out;
  const auto start = std::chrono::steady_clock::now();
  const Status status = load_gltf(path, {mode}, out);
  if (seconds != nullptr)
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(status.is_ok()) << status.message();
  expect_well_formed(out, relative);
  return out;
}

// ---------------------------------------------------------------------------
// Small files written here

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("proxima_gltf_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

using Bytes = std::vector<unsigned char>;

inline void write_file(const std::string& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  ASSERT_TRUE(out.good()) << path;
}
inline void write_file(const std::string& path, const Bytes& bytes) {
  write_file(path, bytes.data(), bytes.size());
}
inline void write_file(const std::string& path, const std::string& text) {
  write_file(path, text.data(), text.size());
}

inline Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Little-endian values (the test hosts are little-endian, as glTF).
template <class T>
inline void put(Bytes& b, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  b.insert(b.end(), raw, raw + sizeof(T));
}
template <class T>
inline void put_all(Bytes& b, std::initializer_list<T> values) {
  for (const T v : values) put(b, v);
}
inline void pad4(Bytes& b) {
  while (b.size() % 4 != 0) b.push_back(0);
}
inline void put_floats(Bytes& b, std::initializer_list<float> values) {
  for (const float v : values) put(b, v);
}

// A .gltf whose one buffer is the .bin beside it; `body` is the rest of the
// top-level JSON object.
inline std::string write_gltf(const TempDir& dir, const std::string& body, const Bytes& bin,
                              const std::string& name = "test") {
  write_file(dir.file(name + ".bin"), bin);
  const std::string json = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"" + name +
                           ".bin\",\"byteLength\":" + std::to_string(bin.size()) + "}]," + body + "}";
  write_file(dir.file(name + ".gltf"), json);
  return dir.file(name + ".gltf");
}

// One node (0) with mesh 0; `meshes`, `views` and `accessors` are JSON arrays.
inline std::string one_node(const std::string& meshes, const std::string& views,
                            const std::string& accessors) {
  return "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\"meshes\":" + meshes +
         ",\"bufferViews\":" + views + ",\"accessors\":" + accessors;
}

inline std::string view(std::size_t offset, std::size_t length, std::size_t stride = 0) {
  return "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
         ",\"byteLength\":" + std::to_string(length) +
         (stride != 0 ? ",\"byteStride\":" + std::to_string(stride) : "") + "}";
}

inline std::string accessor(int view_index, std::size_t count, int component_type, const char* type,
                            const std::string& extra = "") {
  return "{" + (view_index >= 0 ? "\"bufferView\":" + std::to_string(view_index) + "," : std::string()) +
         "\"count\":" + std::to_string(count) + ",\"componentType\":" + std::to_string(component_type) +
         ",\"type\":\"" + type + "\"" + extra + "}";
}

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;

inline std::vector<GltfMesh> load_ok(const std::string& path, GltfSceneMode mode = GltfSceneMode::Merged) {
  std::vector<GltfMesh> out;
  const Status status = load_gltf(path, {mode}, out);
  EXPECT_TRUE(status.is_ok()) << status.message();
  expect_well_formed(out, path);
  return out;
}

inline std::string load_error(const std::string& path, StatusCode code = StatusCode::ParseError) {
  std::vector<GltfMesh> out;
  const Status status = load_gltf(path, {}, out);
  EXPECT_EQ(status.code(), code) << status.message();
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(contains(status.message(), path)) << status.message();
  return status.message();
}

// Five vertices in the z = 0 plane, for strips and fans.
inline Bytes five_vertices(const float (&xy)[5][2]) {
  Bytes b;
  for (const auto& v : xy) put_floats(b, {v[0], v[1], 0.0f});
  return b;
}

// Signed area of triangle t (its z normal), to compare windings.
inline double winding(const GltfMesh& m, std::size_t t) {
  const double* a = &m.positions[3 * std::size_t{m.indices[3 * t]}];
  const double* b = &m.positions[3 * std::size_t{m.indices[3 * t + 1]}];
  const double* c = &m.positions[3 * std::size_t{m.indices[3 * t + 2]}];
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

}  // namespace prox::io::gltf_test
