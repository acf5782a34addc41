// glTF loading: every shared glTF asset against the numbers of
// shared/assets/MANIFEST.md (or, where the manifest gives none, against the
// file's own JSON accessor min/max, read independently).
#include "gltf_test_files.h"

namespace prox::io {
namespace {

using namespace gltf_test;

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
    // Skinned, morphed and animated (MANIFEST.md's second table; its "tris"
    // is per mesh: RecursiveSkeletons' 76-triangle mesh is instanced by 84
    // skinned nodes, 6,384 in the scene).
    {"gltf/SimpleSkin.gltf", 8},
    {"gltf/RiggedFigure.glb", 256},
    {"gltf/RecursiveSkeletons.glb", 6384},
    {"gltf/SimpleMorph.gltf", 1},
    {"gltf/AnimatedMorphCube.glb", 12},
    {"gltf/MorphPrimitivesTest.glb", 32},
    {"gltf/InterpolationTest.glb", 110},
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

// Skinned: the cylinder (local x, y in [-1, 1], z in +-4.575) posed by its
// skin at rest (joint world x inverse bind matrix; its node's transform is
// ignored, as glTF requires). That is its bind coordinates under Z_UP *
// Armature, which map (x, y, z) to (y, z, x), turned a quarter about the
// cylinder's axis: the same box. gltf_rig_test.cpp checks every vertex.
TEST(GltfAssets, RiggedSimpleAtRest) {
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

}  // namespace
}  // namespace prox::io
