// glTF loading: every shared glTF asset against the numbers of
// shared/assets/MANIFEST.md (or, where the manifest gives none, against the
// file's own JSON accessor min/max, read independently), every primitive mode,
// accessor encoding and node transform on small files written here, and
// truncated, corrupted and inconsistent files, which must give an error.
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

namespace prox::io {
namespace {

namespace fs = std::filesystem;

std::string asset(const std::string& relative) {
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + relative;
}

bool contains(const std::string& haystack, const std::string& needle) {
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
Bounds bounds(const std::vector<GltfMesh>& meshes) {
  Bounds b;
  for (const GltfMesh& m : meshes)
    for (const std::uint32_t i : m.indices) b.add(&m.positions[3 * std::size_t{i}]);
  return b;
}
Bounds bounds(const GltfMesh& mesh) { return bounds(std::vector<GltfMesh>{mesh}); }

std::size_t triangles(const std::vector<GltfMesh>& meshes) {
  std::size_t n = 0;
  for (const GltfMesh& m : meshes) n += m.indices.size() / 3;
  return n;
}

// Every soup well formed: whole triangles, indices in range, finite positions.
void expect_well_formed(const std::vector<GltfMesh>& meshes, const std::string& what) {
  for (const GltfMesh& m : meshes) {
    EXPECT_EQ(m.positions.size() % 3, 0u) << what;
    EXPECT_EQ(m.indices.size() % 3, 0u) << what;
    const std::size_t n = m.positions.size() / 3;
    for (const std::uint32_t i : m.indices) ASSERT_LT(i, n) << what;
    for (const double x : m.positions) ASSERT_TRUE(std::isfinite(x)) << what;
  }
}

void expect_bounds(const Bounds& b, const double (&lo)[3], const double (&hi)[3], double tolerance,
                   const std::string& what) {
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(b.lo[a], lo[a], tolerance) << what << " axis " << a;
    EXPECT_NEAR(b.hi[a], hi[a], tolerance) << what << " axis " << a;
  }
}

void expect_size(const Bounds& b, double x, double y, double z, double tolerance, const std::string& what) {
  EXPECT_NEAR(b.size(0), x, tolerance) << what;
  EXPECT_NEAR(b.size(1), y, tolerance) << what;
  EXPECT_NEAR(b.size(2), z, tolerance) << what;
}

// Loads a shared asset; a missing assets folder or file fails the test.
std::vector<GltfMesh> load_asset(const std::string& relative, GltfSceneMode mode = GltfSceneMode::Merged,
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
// The shared assets

// Scene triangle counts ("tris (mesh / scene)", the scene column) of MANIFEST.md.
struct AssetCount {
  const char* file;
  std::size_t triangles;
};
const AssetCount kAssets[] = {
    {"gltf/2CylinderEngine.glb", 121496},
    {"gltf/ReciprocatingSaw.glb", 198470},
    {"gltf/Box.glb", 12},
    {"gltf/Duck.glb", 4212},
    {"gltf/DamagedHelmet.glb", 15452},
    {"gltf/OrientationTest.glb", 524},
    {"gltf/RiggedSimple.glb", 188},
    {"gltf/Suzanne/Suzanne.gltf", 3936},
    {"gltf/TriangleWithoutIndices/TriangleWithoutIndices.gltf", 1},
    {"gltf/SimpleSparseAccessor/SimpleSparseAccessor.gltf", 12},
    {"gltf/Duck-Quantized/Duck.gltf", 4212},
    {"bunny.glb", 27864},
};
const char kDraco[] = "gltf/Duck-Draco/Duck.gltf";  // refused: Draco is not decoded

TEST(GltfAssets, SharedAssetsArePresent) {
  ASSERT_TRUE(fs::is_directory(asset("gltf")))
      << "the shared assets folder " << asset("gltf")
      << " is missing: the glTF tests need the shared assets (../shared/assets beside the repository, or "
         "-DPROX_SHARED_ASSETS_DIR)";
}

// Every .gltf/.glb on disk has its expectation here, so none goes untested.
TEST(GltfAssets, EveryFileIsCovered) {
  ASSERT_TRUE(fs::is_directory(asset("gltf"))) << "missing shared assets folder " << asset("gltf");
  std::set<std::string> expected{kDraco};
  for (const AssetCount& a : kAssets) expected.insert(a.file);
  std::set<std::string> on_disk{"bunny.glb"};
  for (const auto& entry : fs::recursive_directory_iterator(asset("gltf"))) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".gltf" || ext == ".glb")
      on_disk.insert(fs::relative(entry.path(), asset("")).generic_string());
  }
  EXPECT_EQ(on_disk, expected);
}

TEST(GltfAssets, SceneTriangleCounts) {
  for (const AssetCount& a : kAssets) {
    SCOPED_TRACE(a.file);
    double seconds = 0.0;
    const std::vector<GltfMesh> merged = load_asset(a.file, GltfSceneMode::Merged, &seconds);
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_EQ(triangles(merged), a.triangles);
    EXPECT_EQ(merged[0].name, fs::path(a.file).stem().string());
    const std::vector<GltfMesh> per_node = load_asset(a.file, GltfSceneMode::PerNode);
    EXPECT_EQ(triangles(per_node), a.triangles);
    std::cout << "[ load     ] " << a.file << ": " << triangles(merged) << " triangles in " << seconds * 1e3
              << " ms\n";
  }
}

TEST(GltfAssets, DracoIsRefusedByName) {
  std::vector<GltfMesh> out;
  const Status status = load_gltf(asset(kDraco), {}, out);
  EXPECT_EQ(status.code(), StatusCode::Unsupported) << status.message();
  EXPECT_TRUE(contains(status.message(), "KHR_draco_mesh_compression")) << status.message();
  EXPECT_TRUE(contains(status.message(), "Duck-Draco/Duck.gltf")) << status.message();
  EXPECT_TRUE(out.empty());
}

// The parent node's Z-up to Y-up matrix maps (x, y, z) to (x, z, -y): the
// unit cube stays the unit cube, but its first triangle (on the z = +0.5 face
// in the file) lands on y = +0.5. A transposed matrix would put it on -0.5.
TEST(GltfAssets, BoxUnderItsZUpToYUpMatrix) {
  const std::vector<GltfMesh> box = load_asset("gltf/Box.glb");
  ASSERT_EQ(triangles(box), 12u);
  expect_bounds(bounds(box), {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, 1e-12, "Box");
  const GltfMesh& m = box[0];
  const double want[3][3] = {{-0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {-0.5, 0.5, -0.5}};
  for (int v = 0; v < 3; ++v)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(m.positions[3 * std::size_t{m.indices[v]} + a], want[v][a], 1e-12);
  // Closed and wound outwards after the transform: signed volume +1.
  double volume = 0.0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const double* p = &m.positions[3 * std::size_t{m.indices[t]}];
    const double* q = &m.positions[3 * std::size_t{m.indices[t + 1]}];
    const double* r = &m.positions[3 * std::size_t{m.indices[t + 2]}];
    volume += p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
              p[2] * (q[0] * r[1] - q[1] * r[0]);
  }
  EXPECT_NEAR(volume / 6.0, 1.0, 1e-12);
}

// Duck.glb: accessor min/max (JSON) times the root node's 0.01 scale; the
// manifest's world box is 1.655 x 1.54 x 1.153. The quantized duck (uint16
// positions, dequantized by its node's scale 1.01e-4 and translation) gives
// the same box up to half a quantization step.
TEST(GltfAssets, DuckAndQuantizedDuckShareTheirWorldBox) {
  const Bounds duck = bounds(load_asset("gltf/Duck.glb"));
  const double s = 0.009999999776482582;
  expect_bounds(duck, {-69.29850006103516 * s, 9.929369926452637 * s, -61.32819747924805 * s},
                {96.17990112304688 * s, 163.97000122070312 * s, 53.92519760131836 * s}, 1e-9, "Duck.glb");
  expect_size(duck, 1.655, 1.54, 1.153, 1e-3, "Duck.glb");

  const Bounds quantized = bounds(load_asset("gltf/Duck-Quantized/Duck.gltf"));
  const double step = 0.000101006161;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(quantized.lo[a], duck.lo[a], step) << "axis " << a;
    EXPECT_NEAR(quantized.hi[a], duck.hi[a], step) << "axis " << a;
  }
  expect_size(quantized, 1.655, 1.54, 1.153, 1e-3, "Duck-Quantized");
}

// Three of its 14 vertices are replaced through `sparse`: y reaches 4 (the
// accessor max is [6, 4, 0]); without the substitution it stops at 1.
TEST(GltfAssets, SimpleSparseAccessorAppliesTheSubstitution) {
  const std::vector<GltfMesh> m = load_asset("gltf/SimpleSparseAccessor/SimpleSparseAccessor.gltf");
  EXPECT_EQ(triangles(m), 12u);
  expect_bounds(bounds(m), {0, 0, 0}, {6, 4, 0}, 0.0, "SimpleSparseAccessor");
}

TEST(GltfAssets, TriangleWithoutIndices) {
  const std::vector<GltfMesh> m = load_asset("gltf/TriangleWithoutIndices/TriangleWithoutIndices.gltf");
  ASSERT_EQ(triangles(m), 1u);
  EXPECT_EQ(m[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
  expect_bounds(bounds(m), {0, 0, 0}, {1, 1, 0}, 0.0, "TriangleWithoutIndices");
}

// External .bin beside the .gltf; the two PNGs are not needed.
TEST(GltfAssets, SuzanneWithExternalBuffer) {
  const std::vector<GltfMesh> m = load_asset("gltf/Suzanne/Suzanne.gltf", GltfSceneMode::PerNode);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].name, "Suzanne");
  EXPECT_EQ(triangles(m), 3936u);
  expect_bounds(bounds(m), {-1.336914, -0.974609, -0.800781}, {1.336914, 0.950195, 0.825684}, 1e-6,
                "Suzanne");
}

// One node rotated +90 degrees about X by a quaternion: (x, y, z) -> (x, -z, y).
TEST(GltfAssets, DamagedHelmetQuaternion) {
  const std::vector<GltfMesh> m = load_asset("gltf/DamagedHelmet.glb");
  EXPECT_EQ(triangles(m), 15452u);
  expect_bounds(bounds(m), {-0.9474585652351379, -0.900973916053772, -1.18715500831604},
                {0.9424954056739807, 0.9009949564933777, 0.8128451108932495}, 1e-6, "DamagedHelmet");
}

// Skinned: the cylinder (local x, y in [-1, 1], z in +-4.575) in its bind
// coordinates under its node transforms, Z_UP * Armature, which together map
// (x, y, z) to (y, z, x).
TEST(GltfAssets, RiggedSimpleInBindPoseUnderItsNodes) {
  const std::vector<GltfMesh> m = load_asset("gltf/RiggedSimple.glb");
  EXPECT_EQ(triangles(m), 188u);
  expect_bounds(bounds(m), {-0.9999995827674866, -4.575077056884766, -1.0}, {1.0, 4.575077056884766, 1.0},
                1e-6, "RiggedSimple");
}

// Each arrow's node rotates it (quaternion for X1/Y1/Z1, matrix for X2/Y2/Z2)
// so that its tip touches its target, whose pose is baked into its vertices.
// The tip is the face 3.02 from the node's origin (every other arrow vertex is
// within 2.87); its 7 vertices lie 0.003 from the target's box. A transposed
// rotation misses by 0.25 (X2) to 5.6 (Y1); the boxes alone would not tell,
// as X2's and Y2's transposed arrows still touch their targets' boxes.
TEST(GltfAssets, OrientationTestArrowsPointAtTheirTargets) {
  const std::vector<GltfMesh> nodes = load_asset("gltf/OrientationTest.glb", GltfSceneMode::PerNode);
  ASSERT_EQ(nodes.size(), 13u);
  EXPECT_EQ(triangles(nodes), 524u);
  std::map<std::string, const GltfMesh*> by_name;
  for (const GltfMesh& m : nodes) by_name[m.name] = &m;
  struct Arrow {
    const char* axis;
    double origin[3];  // the node's translation (TRS) or matrix column 3, from the JSON
  };
  const Arrow arrows[] = {{"X1", {5, 0, 0}},  {"X2", {-5, 0, 0}}, {"Y1", {0, 5, 0}},
                          {"Y2", {0, -5, 0}}, {"Z1", {0, 0, 5}},  {"Z2", {0, 0, -5}}};
  for (const Arrow& a : arrows) {
    SCOPED_TRACE(a.axis);
    const auto arrow = by_name.find(std::string("Arrow") + a.axis);
    const auto target = by_name.find(std::string("Target") + a.axis);
    ASSERT_NE(arrow, by_name.end());
    ASSERT_NE(target, by_name.end());
    const Bounds box = bounds(*target->second);
    int tips = 0;
    const std::vector<double>& p = arrow->second->positions;
    for (std::size_t v = 0; v < p.size(); v += 3) {
      const double d = std::hypot(p[v] - a.origin[0], p[v + 1] - a.origin[1], p[v + 2] - a.origin[2]);
      if (d < 2.95) continue;
      ++tips;
      double outside = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double gap = std::max({0.0, box.lo[k] - p[v + k], p[v + k] - box.hi[k]});
        outside += gap * gap;
      }
      EXPECT_LT(std::sqrt(outside), 0.01) << "tip vertex " << v / 3;
    }
    EXPECT_EQ(tips, 7);
  }
}

// COLLADA2GLTF CAD output: 67 mesh instances over 29 meshes, 6 levels deep.
TEST(GltfAssets, TwoCylinderEnginePerNode) {
  const std::vector<GltfMesh> merged = load_asset("gltf/2CylinderEngine.glb");
  expect_size(bounds(merged), 743, 273, 268, 1.0, "2CylinderEngine");
  const std::vector<GltfMesh> per_node = load_asset("gltf/2CylinderEngine.glb", GltfSceneMode::PerNode);
  EXPECT_EQ(per_node.size(), 67u);
  EXPECT_EQ(triangles(per_node), 121496u);
  EXPECT_EQ(triangles(per_node), triangles(merged));
  const Bounds a = bounds(merged);
  const Bounds b = bounds(per_node);
  expect_bounds(b, a.lo, a.hi, 0.0, "per node vs merged");
}

TEST(GltfAssets, ReciprocatingSawPerNode) {
  const std::vector<GltfMesh> merged = load_asset("gltf/ReciprocatingSaw.glb");
  expect_size(bounds(merged), 375, 84, 149, 1.0, "ReciprocatingSaw");
  const std::vector<GltfMesh> per_node = load_asset("gltf/ReciprocatingSaw.glb", GltfSceneMode::PerNode);
  EXPECT_EQ(per_node.size(), 113u);
  EXPECT_EQ(triangles(per_node), 198470u);
}

// bunny.glb was written from bunny.obj: same vertex order and indices, float32
// positions (at most 7.5e-9 apart), box about 0.155 x 0.154 x 0.120.
TEST(GltfAssets, BunnyGlbMatchesBunnyObj) {
  const std::vector<GltfMesh> glb = load_asset("bunny.glb");
  ASSERT_EQ(glb.size(), 1u);
  EXPECT_EQ(triangles(glb), 27864u);
  ObjData obj;
  const Status status = read_obj(asset("bunny.obj"), obj);
  ASSERT_TRUE(status.is_ok()) << status.message();
  EXPECT_EQ(glb[0].indices, obj.indices);
  ASSERT_EQ(glb[0].positions.size(), obj.positions.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < obj.positions.size(); ++i)
    worst = std::max(worst, std::abs(glb[0].positions[i] - obj.positions[i]));
  EXPECT_LE(worst, 1e-8);
  expect_size(bounds(glb), 0.155, 0.154, 0.120, 1e-3, "bunny.glb");
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

void write_file(const std::string& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  ASSERT_TRUE(out.good()) << path;
}
void write_file(const std::string& path, const Bytes& bytes) { write_file(path, bytes.data(), bytes.size()); }
void write_file(const std::string& path, const std::string& text) {
  write_file(path, text.data(), text.size());
}

Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Little-endian values (the test hosts are little-endian, as glTF).
template <class T>
void put(Bytes& b, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  b.insert(b.end(), raw, raw + sizeof(T));
}
template <class T>
void put_all(Bytes& b, std::initializer_list<T> values) {
  for (const T v : values) put(b, v);
}
void pad4(Bytes& b) {
  while (b.size() % 4 != 0) b.push_back(0);
}
void put_floats(Bytes& b, std::initializer_list<float> values) {
  for (const float v : values) put(b, v);
}

// A .gltf whose one buffer is the .bin beside it; `body` is the rest of the
// top-level JSON object.
std::string write_gltf(const TempDir& dir, const std::string& body, const Bytes& bin,
                       const std::string& name = "test") {
  write_file(dir.file(name + ".bin"), bin);
  const std::string json = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"" + name +
                           ".bin\",\"byteLength\":" + std::to_string(bin.size()) + "}]," + body + "}";
  write_file(dir.file(name + ".gltf"), json);
  return dir.file(name + ".gltf");
}

// One node (0) with mesh 0; `meshes`, `views` and `accessors` are JSON arrays.
std::string one_node(const std::string& meshes, const std::string& views, const std::string& accessors) {
  return "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\"meshes\":" + meshes +
         ",\"bufferViews\":" + views + ",\"accessors\":" + accessors;
}

std::string view(std::size_t offset, std::size_t length, std::size_t stride = 0) {
  return "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
         ",\"byteLength\":" + std::to_string(length) +
         (stride != 0 ? ",\"byteStride\":" + std::to_string(stride) : "") + "}";
}

std::string accessor(int view_index, std::size_t count, int component_type, const char* type,
                     const std::string& extra = "") {
  return "{" + (view_index >= 0 ? "\"bufferView\":" + std::to_string(view_index) + "," : std::string()) +
         "\"count\":" + std::to_string(count) + ",\"componentType\":" + std::to_string(component_type) +
         ",\"type\":\"" + type + "\"" + extra + "}";
}

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;

std::vector<GltfMesh> load_ok(const std::string& path, GltfSceneMode mode = GltfSceneMode::Merged) {
  std::vector<GltfMesh> out;
  const Status status = load_gltf(path, {mode}, out);
  EXPECT_TRUE(status.is_ok()) << status.message();
  expect_well_formed(out, path);
  return out;
}

std::string load_error(const std::string& path, StatusCode code = StatusCode::ParseError) {
  std::vector<GltfMesh> out;
  const Status status = load_gltf(path, {}, out);
  EXPECT_EQ(status.code(), code) << status.message();
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(contains(status.message(), path)) << status.message();
  return status.message();
}

// Five vertices in the z = 0 plane, for strips and fans.
Bytes five_vertices(const float (&xy)[5][2]) {
  Bytes b;
  for (const auto& v : xy) put_floats(b, {v[0], v[1], 0.0f});
  return b;
}

// Signed area of triangle t (its z normal), to compare windings.
double winding(const GltfMesh& m, std::size_t t) {
  const double* a = &m.positions[3 * std::size_t{m.indices[3 * t]}];
  const double* b = &m.positions[3 * std::size_t{m.indices[3 * t + 1]}];
  const double* c = &m.positions[3 * std::size_t{m.indices[3 * t + 2]}];
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

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
