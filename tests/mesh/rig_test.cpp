// The rig on hand-made scenes: sampler interpolation at chosen times, the
// node hierarchy, skinning with given joint matrices, morph weights, and
// the consistency checks of finalize().
#include "mesh/rig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace prox::rig {
namespace {

Sampler scalar(Interpolation i, std::vector<double> times, std::vector<double> values) {
  Sampler s;
  s.interpolation = i;
  s.times = std::move(times);
  s.values = std::move(values);
  s.width = 1;
  return s;
}

TEST(RigSampler, StepLinearAndCubicAtChosenTimes) {
  double v = 0.0;
  const Sampler step = scalar(Interpolation::Step, {1, 2, 4}, {10, 20, 40});
  sample(step, 0.0, false, &v);
  EXPECT_EQ(v, 10.0);  // before the first keyframe: the first value
  sample(step, 1.999, false, &v);
  EXPECT_EQ(v, 10.0);
  sample(step, 2.0, false, &v);
  EXPECT_EQ(v, 20.0);
  sample(step, 9.0, false, &v);
  EXPECT_EQ(v, 40.0);  // after the last: the last value

  const Sampler linear = scalar(Interpolation::Linear, {1, 2, 4}, {10, 20, 40});
  sample(linear, 3.0, false, &v);
  EXPECT_DOUBLE_EQ(v, 30.0);
  sample(linear, 1.25, false, &v);
  EXPECT_DOUBLE_EQ(v, 12.5);

  // Cubic: (in-tangent, value, out-tangent) per keyframe. Between t = 0 and
  // t = 2 (td = 2) from 0 with out-tangent 3 to 1 with in-tangent -1, at
  // u = 0.5: h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = -0.125, so
  // 0.5 * 0 + 2 * 0.125 * 3 + 0.5 * 1 + 2 * (-0.125) * (-1) = 1.5.
  const Sampler cubic = scalar(Interpolation::CubicSpline, {0, 2}, {7, 0, 3, -1, 1, 9});
  sample(cubic, 1.0, false, &v);
  EXPECT_DOUBLE_EQ(v, 1.5);
  sample(cubic, 2.0, false, &v);
  EXPECT_EQ(v, 1.0);  // the value, not a tangent
}

TEST(RigSampler, SlerpTakesTheShorterArc) {
  const double s = std::sqrt(0.5);
  // The identity to 90 degrees about z, halfway: 45 degrees.
  Quat q = slerp({0, 0, 0, 1}, {0, 0, s, s}, 0.5);
  EXPECT_NEAR(q.z, std::sin(M_PI / 8), 1e-15);
  EXPECT_NEAR(q.w, std::cos(M_PI / 8), 1e-15);
  // The same rotation given as its negative quaternion: still 45 degrees,
  // not the long way round.
  q = slerp({0, 0, 0, 1}, {0, 0, -s, -s}, 0.5);
  EXPECT_NEAR(q.z, std::sin(M_PI / 8), 1e-15);
  EXPECT_NEAR(q.w, std::cos(M_PI / 8), 1e-15);
}

// Two joints in a chain, one triangle skinned to them, and a morph target.
Rig two_joints() {
  Rig rig;
  rig.nodes.resize(3);
  rig.nodes[1].parent = -1;
  rig.nodes[2].parent = 1;
  rig.nodes[2].rest.translation = Vec3(1, 0, 0);
  rig.nodes[0].weights = {0.0};
  rig.skins.push_back({"skin", {1, 2}, {Mat4(1.0), Mat4(1.0)}});
  RigMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  mesh.targets = {{Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(0, 0, 0)}};
  mesh.influences = 4;
  mesh.joints = {0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
  mesh.weights = {1, 0, 0, 0, 0.5, 0.5, 0, 0, 1, 0, 0, 0};
  rig.meshes.push_back(mesh);
  rig.instances.push_back({0, 0, 0, 0});
  rig.vertex_count = 3;
  return rig;
}

TEST(Rig, SkinsMorphsAndTakesJointMatrices) {
  Rig rig = two_joints();
  Status status;
  ASSERT_TRUE(rig.finalize(status)) << status.message();
  std::vector<Vec3> p;
  Pose pose = rig.rest_pose();
  rig.positions(pose, {}, p);
  EXPECT_EQ(p, (std::vector<Vec3>{{0, 0, 0}, {1.5, 0, 0}, {1, 1, 0}}));
  // Joint 1 turned a quarter about z (its child moves with it).
  pose.local[1].rotation = Quat(0, 0, std::sqrt(0.5), std::sqrt(0.5));
  rig.positions(pose, {}, p);
  EXPECT_NEAR(p[2].x, -1.0, 1e-15);  // (0,1,0) + (1,0,0) rotated: (-1, 1, 0)
  EXPECT_NEAR(p[2].y, 1.0, 1e-15);
  // Morph weight 0.5 lifts vertex 0 by half its delta, before skinning.
  ASSERT_EQ(rig.morph_weight_count(), 1u);
  const double w = 0.5;
  pose = rig.rest_pose();
  rig.set_morph_weights(&w, pose);
  rig.positions(pose, {}, p);
  EXPECT_EQ(p[0], Vec3(0, 0, 0.5));
  // Given joint world matrices replace the nodes': joint 1 at y = 2.
  Mat4 up(1.0);
  up[3] = glm::dvec4(0, 2, 0, 1);
  rig.positions(rig.rest_pose(), {{Mat4(1.0), up}}, p);
  EXPECT_EQ(p[2], Vec3(0, 3, 0));
}

TEST(Rig, FinalizeNamesWhatDoesNotFit) {
  Status status;
  Rig rig = two_joints();
  rig.nodes[1].parent = 2;  // 1 -> 2 -> 1
  EXPECT_FALSE(rig.finalize(status));
  EXPECT_NE(status.message().find("2 nodes are on a cycle of parents"), std::string::npos)
      << status.message();
  rig = two_joints();
  rig.meshes[0].joints[4] = 7;
  EXPECT_FALSE(rig.finalize(status));
  EXPECT_NE(status.message().find("joint 7 is past skin 0's 2 joints"), std::string::npos)
      << status.message();
  rig = two_joints();
  rig.vertex_count = 4;
  EXPECT_FALSE(rig.finalize(status));
  EXPECT_NE(status.message().find("the instances hold 3 vertices, not 4"), std::string::npos)
      << status.message();
}

}  // namespace
}  // namespace prox::rig
