// glTF skins, morph targets and animation through the C API: every rigged
// sample's mesh (welded, as proxMesh_GetTriangles hands it out) after
// proxMesh_Animate at several times equals an independent evaluation of the
// file (tests/io/gltf_reference.cpp); the animations' names and durations
// against the file's JSON; joint matrices and morph weights given by the
// caller; misuse refused by name; the float-weight warning.
#include "expect.h"
#include "gltf_reference.h"
#include "gltf_rig_files.h"

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

namespace {

std::string asset(const std::string& relative) {
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + relative;
}

struct Fixture {
  proxWorldId world{};
  Fixture() {
    proxWorldDef def = proxDefaultWorldDef();
    EXPECT_EQ(proxCreateWorld(&def, &world), PROX_SUCCESS) << proxGetLastError();
  }
  ~Fixture() { proxWorld_Destroy(world); }
  proxMeshId load(const std::string& relative) {
    proxMeshId mesh{};
    EXPECT_EQ(proxWorld_LoadMesh(world, asset(relative).c_str(), &mesh), PROX_SUCCESS) << proxGetLastError();
    return mesh;
  }
  proxMeshId load_memory(const std::string& text) {
    proxMeshId mesh{};
    EXPECT_EQ(proxWorld_LoadMeshFromMemory(world, text.data(), text.size(), "skinned.gltf", &mesh),
              PROX_SUCCESS)
        << proxGetLastError();
    return mesh;
  }
};

struct MeshData {
  std::vector<double> positions;
  std::vector<uint32_t> indices;
};
MeshData triangles_of(proxMeshId mesh) {
  MeshData d;
  uint32_t vertices = 0, triangles = 0;
  proxMesh_GetTriangles(mesh, nullptr, 0, &vertices, nullptr, 0, &triangles);
  d.positions.resize(3 * std::size_t{vertices});
  d.indices.resize(3 * std::size_t{triangles});
  EXPECT_EQ(proxMesh_GetTriangles(mesh, d.positions.data(), vertices, &vertices, d.indices.data(), triangles,
                                  &triangles),
            PROX_SUCCESS)
      << proxGetLastError();
  return d;
}

// The reference's triangles the mesh keeps: those whose corners are three
// distinct positions at rest (the mesh drops the others after welding), in
// order.
std::vector<bool> kept_at_rest(const gltf_reference::Document& doc) {
  std::vector<bool> kept;
  for (const auto& t : gltf_reference::triangles(doc, -1, 0.0)) {
    const auto same = [&](int a, int b) {
      return t[3 * a] == t[3 * b] && t[3 * a + 1] == t[3 * b + 1] && t[3 * a + 2] == t[3 * b + 2];
    };
    kept.push_back(!same(0, 1) && !same(1, 2) && !same(0, 2));
  }
  return kept;
}

// The largest distance from a mesh corner to the reference's, over the kept
// triangles in order.
double worst_gap(const MeshData& mesh, const std::vector<std::array<double, 9>>& reference,
                 const std::vector<bool>& kept) {
  std::size_t t = 0;
  double worst = 0.0;
  for (std::size_t r = 0; r < reference.size(); ++r) {
    if (!kept[r]) continue;
    if (3 * t >= mesh.indices.size()) return std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t c = 0; c < 3; ++c)
        worst = std::max(worst,
                         std::abs(mesh.positions[3 * mesh.indices[3 * t + k] + c] - reference[r][3 * k + c]));
    ++t;
  }
  return 3 * t == mesh.indices.size() ? worst : std::numeric_limits<double>::infinity();
}

const char* const kRigged[] = {"gltf/SimpleSkin.gltf",         "gltf/RiggedSimple.glb",
                               "gltf/RiggedFigure.glb",        "gltf/RecursiveSkeletons.glb",
                               "gltf/SimpleMorph.gltf",        "gltf/AnimatedMorphCube.glb",
                               "gltf/MorphPrimitivesTest.glb", "gltf/InterpolationTest.glb"};

TEST(RigCapi, AnimatedMeshesEqualAnIndependentEvaluation) {
  for (const char* file : kRigged) {
    SCOPED_TRACE(file);
    Fixture f;
    const proxMeshId mesh = f.load(file);
    const gltf_reference::Document doc = gltf_reference::open(asset(file));
    const std::vector<bool> kept = kept_at_rest(doc);
    const auto rest = gltf_reference::triangles(doc, -1, 0.0);
    double size = 0.0;
    for (const auto& t : rest)
      for (double x : t) size = std::max(size, std::abs(x));
    const double tolerance = 1e-9 * std::max(1.0, size);
    EXPECT_LE(worst_gap(triangles_of(mesh), rest, kept), tolerance) << "as loaded";

    int32_t count = -1;
    ASSERT_OK(proxMesh_GetAnimationCount(mesh, &count));
    const auto& animations =
        doc.json.contains("animations") ? doc.json["animations"] : nlohmann::json::array();
    ASSERT_EQ(count, static_cast<int32_t>(animations.size()));
    for (int32_t a = 0; a < count; ++a) {
      proxAnimationInfo info{};
      ASSERT_OK(proxMesh_GetAnimationInfo(mesh, a, &info));
      // Duration: the largest keyframe time, from the input accessors' max in the JSON.
      double end = 0.0;
      for (const auto& s : animations[static_cast<std::size_t>(a)]["samplers"])
        end = std::max(end, doc.json["accessors"][s["input"].get<std::size_t>()]["max"][0].get<double>());
      EXPECT_NEAR(info.duration, end, 1e-6 * std::max(1.0, end)) << "animation " << a;
      const std::string name = animations[static_cast<std::size_t>(a)].value("name", std::string());
      if (!name.empty()) {
        EXPECT_EQ(std::string(info.name), name.substr(0, 63));
      }
      for (const double fraction : {0.0, 0.21, 0.5, 0.83, 1.0}) {
        const double t = info.start + fraction * (info.duration - info.start);
        ASSERT_OK(proxMesh_Animate(mesh, a, t));
        EXPECT_LE(worst_gap(triangles_of(mesh), gltf_reference::triangles(doc, a, t), kept), tolerance)
            << "animation " << a << " at " << t << " s";
      }
    }
  }
}

TEST(RigCapi, RigInfoCountsWhatTheFileHas) {
  Fixture f;
  proxRigInfo info{};
  ASSERT_OK(proxMesh_GetRigInfo(f.load("gltf/RecursiveSkeletons.glb"), &info));
  EXPECT_EQ(info.skinCount, 84);
  EXPECT_EQ(info.jointCount, 840);
  EXPECT_EQ(info.morphWeightCount, 0);
  EXPECT_EQ(info.animationCount, 1);
  const proxMeshId cube = f.load("gltf/AnimatedMorphCube.glb");
  ASSERT_OK(proxMesh_GetRigInfo(cube, &info));
  EXPECT_EQ(info.skinCount, 0);
  EXPECT_EQ(info.morphWeightCount, 2);
  const proxMeshId box = f.load("gltf/Box.glb");  // no rig: zeros
  ASSERT_OK(proxMesh_GetRigInfo(box, &info));
  EXPECT_EQ(info.skinCount + info.jointCount + info.morphWeightCount + info.animationCount, 0);
  proxSkinInfo skin{};
  ASSERT_OK(proxMesh_GetSkinInfo(f.load("gltf/RiggedFigure.glb"), 0, &skin));
  EXPECT_EQ(skin.jointCount, 19);
}

// The skinned triangle (gltf_rig_files.h): joint 0 at the origin, joint 1 at
// x = 1, identity inverse bind matrices. Given joint 1 at y = 2 instead:
// (0,0,0) stays, (1,0,0) half on each goes to (1, 1, 0), (0,1,0) to (0, 3, 0).
TEST(RigCapi, JointMatricesFromTheEngine) {
  Fixture f;
  const proxMeshId mesh = f.load_memory(gltf_rig_files::SkinnedTriangle().json());
  double m[32] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,   //
                  1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1};  // column-major: translation 12..14
  ASSERT_OK(proxMesh_SetJointMatrices(mesh, 0, m, 2));
  MeshData d = triangles_of(mesh);
  ASSERT_EQ(d.indices.size(), 3u);
  const double want[3][3] = {{0, 0, 0}, {1, 1, 0}, {0, 3, 0}};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(d.positions[3 * d.indices[k] + c], want[k][c]);

  // Refused by name, the mesh unchanged.
  EXPECT_FAILS(proxMesh_SetJointMatrices(mesh, 0, m, 3), PROX_ERROR_INVALID_ARGUMENT,
               "count is 3 but skin 0 has 2");
  EXPECT_FAILS(proxMesh_SetJointMatrices(mesh, 1, m, 2), PROX_ERROR_INVALID_ARGUMENT,
               "skin 1 does not exist");
  EXPECT_FAILS(proxMesh_SetJointMatrices(mesh, 0, nullptr, 2), PROX_ERROR_INVALID_ARGUMENT,
               "matrices is NULL");
  m[16 + 13] = std::nan("");
  EXPECT_FAILS(proxMesh_SetJointMatrices(mesh, 0, m, 2), PROX_ERROR_INVALID_ARGUMENT,
               "matrices[1] (joint 1) element 13 (column 3, row 1) is nan");
  m[16 + 13] = 2;
  m[16 + 3] = 0.5;
  EXPECT_FAILS(proxMesh_SetJointMatrices(mesh, 0, m, 2), PROX_ERROR_INVALID_ARGUMENT,
               "matrices[1] (joint 1) is not affine");
  m[16 + 12] = 1e60;
  m[16 + 3] = 0;
  EXPECT_FAILS(proxMesh_SetJointMatrices(mesh, 0, m, 2), PROX_ERROR_INVALID_ARGUMENT,
               "vertex 1 at a coordinate of 5e+59, beyond the +-1e50");  // half on joint 1, at x = 1e60
  d = triangles_of(mesh);
  EXPECT_DOUBLE_EQ(d.positions[3 * d.indices[2] + 1], 3.0);
}

// SimpleMorph's weights set by the caller equal the file evaluated with
// those weights as its mesh's defaults.
TEST(RigCapi, MorphWeightsFromTheEngine) {
  Fixture f;
  const proxMeshId mesh = f.load("gltf/SimpleMorph.gltf");
  gltf_reference::Document doc = gltf_reference::open(asset("gltf/SimpleMorph.gltf"));
  const std::vector<bool> kept = kept_at_rest(doc);
  const double weights[2] = {0.25, 0.8};
  ASSERT_OK(proxMesh_SetMorphWeights(mesh, weights, 2));
  for (auto& node : doc.json["nodes"]) node.erase("weights");
  doc.json["meshes"][0]["weights"] = {0.25, 0.8};
  EXPECT_LE(worst_gap(triangles_of(mesh), gltf_reference::triangles(doc, -1, 0.0), kept), 1e-12);

  EXPECT_FAILS(proxMesh_SetMorphWeights(mesh, weights, 3), PROX_ERROR_INVALID_ARGUMENT,
               "count is 3 but the mesh has 2 morph weights");
  const double bad[2] = {0.5, std::numeric_limits<double>::infinity()};
  EXPECT_FAILS(proxMesh_SetMorphWeights(mesh, bad, 2), PROX_ERROR_INVALID_ARGUMENT, "weights[1] is inf");
}

TEST(RigCapi, MisuseIsRefusedByName) {
  Fixture f;
  const proxMeshId box = f.load("gltf/Box.glb");
  EXPECT_FAILS(proxMesh_Animate(box, 0, 0.0), PROX_ERROR_INVALID_ARGUMENT, "the mesh has no rig");
  int32_t count = -1;
  ASSERT_OK(proxMesh_GetAnimationCount(box, &count));
  EXPECT_EQ(count, 0);
  const proxMeshId skin = f.load("gltf/SimpleSkin.gltf");
  EXPECT_FAILS(proxMesh_Animate(skin, 1, 0.0), PROX_ERROR_INVALID_ARGUMENT,
               "animation 1 does not exist (the mesh has 1)");
  EXPECT_FAILS(proxMesh_Animate(skin, -1, 0.0), PROX_ERROR_INVALID_ARGUMENT, "animation -1 does not exist");
  EXPECT_FAILS(proxMesh_Animate(skin, 0, std::nan("")), PROX_ERROR_INVALID_ARGUMENT, "seconds is nan");
  proxAnimationInfo info{};
  EXPECT_FAILS(proxMesh_GetAnimationInfo(skin, 3, &info), PROX_ERROR_INVALID_ARGUMENT,
               "index 3 names no animation (the mesh has 1)");
  EXPECT_FAILS(proxMesh_GetAnimationInfo(skin, 0, nullptr), PROX_ERROR_INVALID_ARGUMENT, "info is NULL");
  EXPECT_FAILS(proxMesh_GetAnimationCount(skin, nullptr), PROX_ERROR_INVALID_ARGUMENT, "count is NULL");
  EXPECT_FAILS(proxMesh_Animate(proxMeshId{}, 0, 0.0), PROX_ERROR_INVALID_HANDLE, "mesh");
  EXPECT_OK(proxMesh_SetMorphWeights(skin, nullptr, 0));  // no morph targets: count 0, nothing to read
}

// A seam: two primitives share the position (0, 1, 0) at rest (welded into
// one vertex), but only the first's morph target moves it. Posed at weight
// 1 the copies part; the first in scene order (primitive 0's, lifted to
// z = 1) places the welded vertex, and the second triangle follows it.
TEST(RigCapi, WeldedVerticesThatPartFollowTheFirst) {
  std::vector<unsigned char> bin;
  const auto put = [&bin](std::initializer_list<float> values) {
    for (const float v : values) {
      unsigned char b[4];
      std::memcpy(b, &v, 4);
      bin.insert(bin.end(), b, b + 4);
    }
  };
  put({0, 0, 0, 1, 0, 0, 0, 1, 0});  // primitive 0 (accessor 0)
  put({0, 0, 0, 0, 0, 0, 0, 0, 1});  // its target: vertex 2 up by 1 (accessor 1)
  put({0, 1, 0, 1, 0, 0, 1, 1, 0});  // primitive 1 (accessor 2), vertex 0 on primitive 0's vertex 2
  put({0, 0, 0, 0, 0, 0, 0, 0, 0});  // its target: nothing moves (accessor 3)
  std::string views, accessors;
  for (int k = 0; k < 4; ++k) {
    views += std::string(k ? "," : "") + "{\"buffer\":0,\"byteOffset\":" + std::to_string(36 * k) +
             ",\"byteLength\":36}";
    accessors += std::string(k ? "," : "") + "{\"bufferView\":" + std::to_string(k) +
                 ",\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}";
  }
  const std::string json =
      "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1}]},"
      "{\"attributes\":{\"POSITION\":2},\"targets\":[{\"POSITION\":3}]}]}],"
      "\"buffers\":[{\"byteLength\":144,\"uri\":\"data:application/octet-stream;base64," +
      gltf_rig_files::base64(bin) + "\"}],\"bufferViews\":[" + views + "],\"accessors\":[" + accessors + "]}";
  Fixture f;
  const proxMeshId mesh = f.load_memory(json);
  proxMeshInfo info{};
  ASSERT_OK(proxMesh_GetInfo(mesh, &info));
  ASSERT_EQ(info.vertexCount, 4u);  // 6 input vertices, (0,1,0) and (1,0,0) welded
  const double one = 1.0;
  ASSERT_OK(proxMesh_SetMorphWeights(mesh, &one, 1));
  const MeshData d = triangles_of(mesh);
  ASSERT_EQ(d.indices.size(), 6u);
  // Both triangles' corner at (0, 1) is the lifted one.
  int lifted = 0;
  for (const uint32_t i : d.indices)
    if (d.positions[3 * i] == 0 && d.positions[3 * i + 1] == 1) {
      EXPECT_EQ(d.positions[3 * i + 2], 1.0);
      ++lifted;
    }
  EXPECT_EQ(lifted, 2);
}

// While the threads run: a static body's mesh and a held tool's are posed
// (their vertices replaced, as proxMesh_SetVertices does).
TEST(RigCapi, PosingWhileTheThreadsRun) {
  Fixture f;
  const proxMeshId wall = f.load("gltf/RiggedSimple.glb");
  const proxMeshId held = f.load("gltf/RiggedSimple.glb");
  proxBodyDef def = proxDefaultBodyDef();
  def.mesh = wall;
  proxBodyId a{}, b{};
  ASSERT_OK(proxWorld_CreateBody(f.world, &def, &a));
  def.mesh = held;
  def.type = PROX_BODY_TOOL;
  def.pose.position = proxVec3{0, 0, 10};
  ASSERT_OK(proxWorld_CreateBody(f.world, &def, &b));
  const MeshData before = triangles_of(wall), held_before = triangles_of(held);
  const proxThreadsDef threads = proxDefaultThreadsDef();
  ASSERT_OK(proxWorld_StartThreads(f.world, &threads));
  EXPECT_OK(proxMesh_Animate(wall, 0, 1.5));
  EXPECT_OK(proxMesh_Animate(held, 0, 1.5));  // a held tool's mesh deforms too
  EXPECT_OK(proxWorld_StopThreads(f.world));
  EXPECT_NE(triangles_of(wall).positions, before.positions);
  EXPECT_NE(triangles_of(held).positions, held_before.positions);
}

// A character's neck with weights summing to 0.18: loaded, normalized, and
// said so in proxMesh_GetWarnings.
TEST(RigCapi, FloatWeightsOffOneWarn) {
  Fixture f;
  gltf_rig_files::SkinnedTriangle t;
  t.weights[4] = t.weights[5] = 0.09;
  const proxMeshId mesh = f.load_memory(t.json());
  int32_t length = 0;
  char text[1024];
  ASSERT_OK(proxMesh_GetWarnings(mesh, text, sizeof text, &length));
  EXPECT_NE(
      std::string(text).find("WEIGHTS_0 accessor 2: the float weights of 1 of 3 vertices do not sum to 1 "
                             "(vertex 1's sum to 0.18)"),
      std::string::npos)
      << text;
}

}  // namespace
