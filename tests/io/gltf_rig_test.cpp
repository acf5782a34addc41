// glTF skins, morph targets and animations: every shared rigged sample loads
// with its rig, and its positions at rest and at several animation times
// equal an independent evaluation (gltf_reference.cpp); sampler
// interpolation by the specification's formulas on InterpolationTest; the
// MUST rules on skins refused with the accessor named.
#include "gltf_reference.h"
#include "gltf_rig_files.h"
#include "gltf_test_files.h"

namespace prox::io {
namespace {

using namespace gltf_test;

struct RiggedAsset {
  const char* file;
  // MANIFEST.md, but targets per morphed mesh: MorphPrimitivesTest has one,
  // in each of its two primitives (the manifest counts 2).
  std::size_t skins, joints, targets, animations;
};
const RiggedAsset kRigged[] = {
    {"gltf/SimpleSkin.gltf", 1, 2, 0, 1},         {"gltf/RiggedSimple.glb", 1, 2, 0, 1},
    {"gltf/RiggedFigure.glb", 1, 19, 0, 1},       {"gltf/RecursiveSkeletons.glb", 84, 840, 0, 1},
    {"gltf/SimpleMorph.gltf", 0, 0, 2, 1},        {"gltf/AnimatedMorphCube.glb", 0, 0, 2, 1},
    {"gltf/MorphPrimitivesTest.glb", 0, 0, 1, 0}, {"gltf/InterpolationTest.glb", 0, 0, 0, 9},
};

std::shared_ptr<const rig::Rig> load_rig(const char* file, GltfMesh& mesh) {
  std::vector<GltfMesh> out = load_asset(file);
  if (out.size() != 1) return nullptr;
  mesh = out[0];
  return mesh.rig;
}

TEST(GltfRig, EveryRiggedSampleLoadsWithItsRig) {
  for (const RiggedAsset& a : kRigged) {
    SCOPED_TRACE(a.file);
    GltfMesh mesh;
    const auto rig = load_rig(a.file, mesh);
    ASSERT_NE(rig, nullptr);
    EXPECT_EQ(rig->skins.size(), a.skins);
    std::size_t joints = 0;
    for (const rig::Skin& s : rig->skins) joints += s.joints.size();
    EXPECT_EQ(joints, a.joints);
    std::size_t targets = 0;
    for (const rig::RigMesh& m : rig->meshes) targets = std::max(targets, m.targets.size());
    EXPECT_EQ(targets, a.targets);
    EXPECT_EQ(rig->animations.size(), a.animations);
    EXPECT_EQ(rig->vertex_count, mesh.positions.size() / 3);
  }
}

// Per node, each instance's vertices are posed at rest too (no rig is kept):
// one after the other they are the merged soup's.
TEST(GltfRig, PerNodeIsPosedAtRestToo) {
  for (const RiggedAsset& a : kRigged) {
    SCOPED_TRACE(a.file);
    const std::vector<GltfMesh> merged = load_asset(a.file);
    const std::vector<GltfMesh> per_node = load_asset(a.file, GltfSceneMode::PerNode);
    ASSERT_EQ(merged.size(), 1u);
    std::vector<double> joined;
    for (const GltfMesh& m : per_node) {
      EXPECT_EQ(m.rig, nullptr);
      joined.insert(joined.end(), m.positions.begin(), m.positions.end());
    }
    EXPECT_EQ(joined, merged[0].positions);
  }
}

// A file without skins, morph targets or animations has no rig.
TEST(GltfRig, StaticFilesHaveNoRig) {
  for (const char* file : {"gltf/Box.glb", "gltf/Duck.glb", "gltf/OrientationTest.glb"}) {
    const std::vector<GltfMesh> out = load_asset(file);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].rig, nullptr) << file;
  }
}

// The SDK's triangles, from `positions` (one per input vertex), against the
// reference's, corner by corner, to rounding relative to the scene's size.
void expect_same_triangles(const GltfMesh& mesh, const std::vector<Vec3>& positions,
                           const std::vector<std::array<double, 9>>& reference, const std::string& what) {
  ASSERT_EQ(mesh.indices.size() / 3, reference.size()) << what;
  double size = 0.0;
  for (const auto& t : reference)
    for (double x : t) size = std::max(size, std::abs(x));
  const double tolerance = 1e-9 * std::max(size, 1.0);
  double worst = 0.0;
  std::size_t worst_triangle = 0;
  for (std::size_t t = 0; t < reference.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3& p = positions[mesh.indices[3 * t + k]];
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(p[c] - reference[t][3 * k + static_cast<std::size_t>(c)]);
        if (d > worst) worst = d, worst_triangle = t;
      }
    }
  EXPECT_LE(worst, tolerance) << what << ": triangle " << worst_triangle << " is " << worst
                              << " from the reference (scene size " << size << ")";
}

// At rest (no animation), then each animation at its start, inside, at the
// end and past it.
TEST(GltfRig, PositionsEqualAnIndependentEvaluation) {
  for (const RiggedAsset& a : kRigged) {
    SCOPED_TRACE(a.file);
    GltfMesh mesh;
    const auto rig = load_rig(a.file, mesh);
    ASSERT_NE(rig, nullptr);
    const gltf_reference::Document doc = gltf_reference::open(asset(a.file));
    std::vector<Vec3> loaded(mesh.positions.size() / 3);
    for (std::size_t v = 0; v < loaded.size(); ++v)
      loaded[v] = Vec3(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    const auto rest = gltf_reference::triangles(doc, -1, 0.0);
    expect_same_triangles(mesh, loaded, rest, "as loaded");
    std::vector<Vec3> positions;
    rig->positions(rig->rest_pose(), {}, positions);
    expect_same_triangles(mesh, positions, rest, "rest pose");
    for (std::size_t n = 0; n < rig->animations.size(); ++n) {
      const rig::Animation& animation = rig->animations[n];
      const double span = animation.end - animation.start;
      for (const double f : {0.0, 0.13, 0.5, 0.77, 1.0, 1.5}) {
        const double t = animation.start + f * span;
        rig::Pose pose = rig->rest_pose();
        rig->animate(n, t, pose);
        rig->positions(pose, {}, positions);
        expect_same_triangles(mesh, positions, gltf_reference::triangles(doc, static_cast<int>(n), t),
                              "animation " + std::to_string(n) + " at " + std::to_string(t) + " s");
      }
    }
  }
}

// The skinned meshes really move (the comparison above is not of two rest
// poses): RiggedSimple's cylinder bends by a good part of its length.
TEST(GltfRig, RiggedSimpleBends) {
  GltfMesh mesh;
  const auto rig = load_rig("gltf/RiggedSimple.glb", mesh);
  ASSERT_NE(rig, nullptr);
  std::vector<Vec3> rest, bent;
  rig->positions(rig->rest_pose(), {}, rest);
  rig::Pose pose = rig->rest_pose();
  rig->animate(0, 0.5 * (rig->animations[0].start + rig->animations[0].end), pose);
  rig->positions(pose, {}, bent);
  double moved = 0.0;
  for (std::size_t v = 0; v < rest.size(); ++v) moved = std::max(moved, glm::length(bent[v] - rest[v]));
  EXPECT_GT(moved, 1.0);
}

// ---------------------------------------------------------------------------
// Interpolation, by hand from the glTF 2.0 formulas on InterpolationTest's
// keyframes (read by the reference reader).

struct Keys {
  std::vector<double> times, values;
};
Keys keys_of(const gltf_reference::Document& doc, int animation) {
  const auto& s = doc.json["animations"][static_cast<std::size_t>(animation)]["samplers"][0];
  return {gltf_reference::accessor(doc, s["input"].get<int>()),
          gltf_reference::accessor(doc, s["output"].get<int>())};
}

TEST(GltfRig, InterpolationFollowsTheSpecification) {
  GltfMesh mesh;
  const auto rig = load_rig("gltf/InterpolationTest.glb", mesh);
  ASSERT_NE(rig, nullptr);
  const gltf_reference::Document doc = gltf_reference::open(asset("gltf/InterpolationTest.glb"));
  ASSERT_EQ(rig->animations.size(), 9u);
  const auto pose_at = [&](std::size_t animation, double t) {
    rig::Pose pose = rig->rest_pose();
    rig->animate(animation, t, pose);
    return pose;
  };
  const double tol = 1e-12;

  // 0 "Step Scale" on node 0: keyframe 1 (0.5) holds until keyframe 2; the
  // first value before the first keyframe, the last after the last.
  {
    const Keys k = keys_of(doc, 0);
    const double mid = 0.5 * (k.times[1] + k.times[2]);
    EXPECT_NEAR(pose_at(0, mid).local[0].scale.x, 0.5, tol);
    EXPECT_NEAR(pose_at(0, k.times[2] - 1e-9).local[0].scale.y, 0.5, tol);
    EXPECT_NEAR(pose_at(0, k.times[2]).local[0].scale.z, 1.0, tol);
    EXPECT_NEAR(pose_at(0, 0.0).local[0].scale.x, 1.0, tol);
    EXPECT_NEAR(pose_at(0, 10.0).local[0].scale.x, k.values.back(), tol);
  }
  // 1 "Linear Scale" on node 3: a quarter of the way from 0.5 to 1.0.
  {
    const Keys k = keys_of(doc, 1);
    const double t = k.times[1] + 0.25 * (k.times[2] - k.times[1]);
    EXPECT_NEAR(pose_at(1, t).local[3].scale.x, 0.5 + 0.25 * (1.0 - 0.5), tol);
  }
  // 2 "CubicSpline Scale" on node 4: tangents 0, so halfway between 1 and
  // 0.5 the Hermite basis gives (1 + 0.5) / 2; at u = 0.25 it gives
  // h00 = 2u^3 - 3u^2 + 1 = 0.84375 of the first value.
  {
    const Keys k = keys_of(doc, 2);
    EXPECT_NEAR(pose_at(2, 0.5 * (k.times[0] + k.times[1])).local[4].scale.x, 0.75, tol);
    const double t = k.times[0] + 0.25 * (k.times[1] - k.times[0]);
    EXPECT_NEAR(pose_at(2, t).local[4].scale.y, 0.84375 * 1.0 + 0.15625 * 0.5, tol);
  }
  // 3 "Step Rotation" on node 5: keyframe 2 (-90 degrees about z) held.
  {
    const Keys k = keys_of(doc, 3);
    const rig::Quat q = pose_at(3, 0.5 * (k.times[2] + k.times[3])).local[5].rotation;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(q[c], k.values[8 + static_cast<std::size_t>(c)], 1e-7);
  }
  // 5 "Linear Rotation" on node 7: halfway from the identity to -45 degrees
  // about z is -22.5 degrees: (0, 0, -sin(11.25), cos(11.25)).
  {
    const Keys k = keys_of(doc, 5);
    const rig::Quat q = pose_at(5, 0.5 * (k.times[0] + k.times[1])).local[7].rotation;
    const double half = 11.25 * 3.14159265358979323846 / 180.0;
    EXPECT_NEAR(q.x, 0.0, 1e-7);
    EXPECT_NEAR(q.y, 0.0, 1e-7);
    EXPECT_NEAR(q.z, -std::sin(half), 1e-7);  // the file's keyframes are float32
    EXPECT_NEAR(q.w, std::cos(half), 1e-7);
  }
  // 4 "CubicSpline Rotation" on node 6: tangents not 0, scaled by the
  // keyframe interval td; the result normalized.
  {
    const Keys k = keys_of(doc, 4);
    const double t0 = k.times[1], t1 = k.times[2], td = t1 - t0, u = 0.3;
    // Keyframe k holds (in-tangent, value, out-tangent), 4 numbers each.
    const auto at = [&](std::size_t key, std::size_t part, std::size_t c) {
      return k.values[12 * key + 4 * part + c];
    };
    double want[4], norm = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
      want[c] = (2 * u * u * u - 3 * u * u + 1) * at(1, 1, c) +
                td * (u * u * u - 2 * u * u + u) * at(1, 2, c) + (-2 * u * u * u + 3 * u * u) * at(2, 1, c) +
                td * (u * u * u - u * u) * at(2, 0, c);
      norm += want[c] * want[c];
    }
    const rig::Quat q = pose_at(4, t0 + u * td).local[6].rotation;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(q[c], want[c] / std::sqrt(norm), tol);
  }
  // 6 "Step Translation" on node 8; 7 "CubicSpline Translation" on node 9
  // (tangents 0: smoothstep); 8 "Linear Translation" on node 10.
  {
    const Keys k = keys_of(doc, 6);
    EXPECT_NEAR(pose_at(6, 0.5 * (k.times[0] + k.times[1])).local[8].translation.y, k.values[1], tol);
    const Keys c = keys_of(doc, 7);
    const double t = c.times[0] + 0.25 * (c.times[1] - c.times[0]);
    EXPECT_NEAR(pose_at(7, t).local[9].translation.y, 0.84375 * c.values[4] + 0.15625 * c.values[13], tol);
    const Keys l = keys_of(doc, 8);
    const double s = l.times[1] + 0.6 * (l.times[2] - l.times[1]);
    EXPECT_NEAR(pose_at(8, s).local[10].translation.y, 0.4 * l.values[4] + 0.6 * l.values[7], tol);
  }
}

// ---------------------------------------------------------------------------
// glTF's MUST rules on skins, on a skinned triangle in memory.

Status load_memory(const std::string& json, std::vector<GltfMesh>& out, std::vector<std::string>* warnings) {
  GltfLoadOptions options;
  options.external_buffers = false;
  return load_gltf_bytes({json.begin(), json.end()}, "skinned.gltf", options, out, warnings);
}

std::string refused(const gltf_rig_files::SkinnedTriangle& t) {
  std::vector<GltfMesh> out;
  const Status status = load_memory(t.json(), out, nullptr);
  EXPECT_EQ(status.code(), StatusCode::ParseError) << status.message();
  EXPECT_TRUE(out.empty());
  return status.message();
}

// Joint 0 at the origin, joint 1 at x = 1, identity inverse bind matrices:
// (0,0,0) on joint 0 stays; (1,0,0) half on each moves by 0.5; (0,1,0) on
// joint 1 moves by 1.
TEST(GltfRigRules, TheSkinnedTriangleIsPosedAtRest) {
  std::vector<GltfMesh> out;
  const Status status = load_memory(gltf_rig_files::SkinnedTriangle().json(), out, nullptr);
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].positions, (std::vector<double>{0, 0, 0, 1.5, 0, 0, 1, 1, 0}));
}

TEST(GltfRigRules, NegativeWeightIsRefused) {
  gltf_rig_files::SkinnedTriangle t;
  t.weights[4] = -0.5;
  t.weights[5] = 1.5;
  const std::string message = refused(t);
  EXPECT_TRUE(contains(message, "WEIGHTS_0 accessor 2: vertex 1 has weight -0.5")) << message;
}

TEST(GltfRigRules, NormalizedIntegerWeightsMustSumToTheirMaximum) {
  gltf_rig_files::SkinnedTriangle t;
  t.weight_type = gltf_rig_files::WeightType::UByte;
  t.weights = {255, 0, 0, 0, 128, 127, 0, 0, 255, 0, 0, 0};
  std::vector<GltfMesh> out;
  EXPECT_TRUE(load_memory(t.json(), out, nullptr).is_ok());
  t.weights[5] = 126;
  std::string message = refused(t);
  EXPECT_TRUE(
      contains(message, "WEIGHTS_0 accessor 2: vertex 1's normalized integer weights sum to 254, not 255"))
      << message;
  t.weight_type = gltf_rig_files::WeightType::UShort;
  t.weights = {65535, 0, 0, 0, 30000, 30000, 0, 0, 65535, 0, 0, 0};
  message = refused(t);
  EXPECT_TRUE(contains(message, "vertex 1's normalized integer weights sum to 60000, not 65535")) << message;
}

TEST(GltfRigRules, JointsMustBeInRange) {
  gltf_rig_files::SkinnedTriangle t;
  t.joints[8] = 5;  // vertex 2, weight 1
  std::string message = refused(t);
  EXPECT_TRUE(contains(message, "JOINTS_0 accessor 1: a vertex has joint 5, but skin 0 has 2 joints"))
      << message;
  // A joint past the skin's is refused even with weight 0.
  t.joints[8] = 1;
  t.joints[11] = 2;
  message = refused(t);
  EXPECT_TRUE(contains(message, "has joint 2, but skin 0 has 2 joints")) << message;
}

TEST(GltfRigRules, AsManyJointsAsWeightsSets) {
  gltf_rig_files::SkinnedTriangle t;
  t.second_joints_set = true;
  const std::string message = refused(t);
  EXPECT_TRUE(contains(message, "mesh 0 primitive 0 has 2 JOINTS_n and 1 WEIGHTS_n")) << message;
}

// A skinned node's every primitive has joints and weights.
TEST(GltfRigRules, EverySkinnedPrimitiveHasJoints) {
  gltf_rig_files::SkinnedTriangle t;
  t.bare_primitive = true;
  const std::string message = refused(t);
  EXPECT_TRUE(contains(message, "node 0 has skin 0 but mesh 0 primitive 1 has no JOINTS_0 and WEIGHTS_0"))
      << message;
}

// Animations: keyframe times strictly increasing; an animated node has
// translation, rotation and scale, not a matrix.
TEST(GltfRigRules, AnimationsFollowTheRules) {
  gltf_rig_files::MorphedTriangle t;
  std::vector<GltfMesh> out;
  Status status = load_memory(t.json(), out, nullptr);
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_NE(out[0].rig, nullptr);
  rig::Pose pose = out[0].rig->rest_pose();
  out[0].rig->animate(0, 1.5, pose);
  EXPECT_EQ(pose.weights[0], std::vector<double>{0.75});

  t.times[1] = 0;
  status = load_memory(t.json(), out, nullptr);
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_TRUE(contains(status.message(),
                       "animation 0 sampler 0: input accessor 2: keyframe 1 at 0 s (glTF: times "
                       "are finite, not negative and strictly increasing)"))
      << status.message();

  t = gltf_rig_files::MorphedTriangle();
  t.path = "translation";
  t.node_matrix = true;
  status = load_memory(t.json(), out, nullptr);
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_TRUE(contains(status.message(), "animation 0 channel 0: node 0 has a matrix")) << status.message();
  t.node_matrix = false;
  status = load_memory(t.json(), out, nullptr);
  ASSERT_TRUE(status.is_ok()) << status.message();
  pose = out[0].rig->rest_pose();
  out[0].rig->animate(0, 0.5, pose);
  EXPECT_EQ(pose.local[0].translation, Vec3(0.25, 0, 0));
}

// A SHOULD: float weights off 1 are normalized, with a warning naming the
// accessor and the worst vertex.
TEST(GltfRigRules, FloatWeightsOffOneAreNormalizedWithAWarning) {
  gltf_rig_files::SkinnedTriangle t;
  t.weights[4] = 0.09;  // vertex 1: 0.09 + 0.09 = 0.18, as on a character's neck
  t.weights[5] = 0.09;
  std::vector<GltfMesh> out;
  std::vector<std::string> warnings;
  const Status status = load_memory(t.json(), out, &warnings);
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(
      contains(warnings[0], "WEIGHTS_0 accessor 2: the float weights of 1 of 3 vertices do not sum to 1"))
      << warnings[0];
  EXPECT_TRUE(contains(warnings[0], "vertex 1's sum to 0.18")) << warnings[0];
  // Normalized: half on each joint, as with weights 0.5 and 0.5.
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].positions[3], 1.5, 1e-7);
}

}  // namespace
}  // namespace prox::io
