// The constrained tool through the C API (docs/coupling.md): the def's tool
// mode and coupling, their errors, proxBody_GetProxyPose beside the device
// pose, and a cube pushed into a cube by proxWorld_Step.
#include "expect.h"

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace {

class Coupling : public ::testing::Test {
 protected:
  void SetUp() override {
    const proxWorldDef def = proxDefaultWorldDef();
    ASSERT_OK(proxCreateWorld(&def, &world_));
    safety_ = def.force.safetyDistance;
    max_force_ = def.force.maxForce;
    big_ = cube(0.01);
    small_ = cube(0.005);
    proxBodyDef a = proxDefaultBodyDef();
    a.mesh = big_;
    ASSERT_OK(proxWorld_CreateBody(world_, &a, &obstacle_));
  }
  void TearDown() override { EXPECT_OK(proxWorld_Destroy(world_)); }

  // A closed cube of half-size h about the origin, wound outwards.
  proxMeshId cube(double h) {
    double positions[24];
    for (int i = 0; i < 8; ++i) {
      positions[3 * i] = (i & 1) ? h : -h;
      positions[3 * i + 1] = (i & 2) ? h : -h;
      positions[3 * i + 2] = (i & 4) ? h : -h;
    }
    const uint32_t indices[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    proxMeshDef def = proxDefaultMeshDef();
    def.positions = positions;
    def.vertexCount = 8;
    def.indices = indices;
    def.triangleCount = 12;
    proxMeshId mesh{};
    EXPECT_OK(proxWorld_CreateMesh(world_, &def, &mesh));
    return mesh;
  }
  proxBodyDef tool_def(double x) const {
    proxBodyDef d = proxDefaultBodyDef();
    d.mesh = small_;
    d.type = PROX_BODY_TOOL;
    d.pose.position = {x, 0.001, 0.002};
    d.toolMode = PROX_TOOL_CONSTRAINED;
    return d;
  }

  proxWorldId world_{};
  proxMeshId big_{}, small_{};
  proxBodyId obstacle_{};
  double safety_ = 0.0, max_force_ = 0.0;
};

TEST_F(Coupling, DefaultsAreTheFreeToolAndAUsableCoupling) {
  const proxBodyDef d = proxDefaultBodyDef();
  EXPECT_EQ(d.toolMode, PROX_TOOL_FREE);
  EXPECT_GT(d.couplingStiffness, 0.0);
  EXPECT_GE(d.couplingDamping, 0.0);
  EXPECT_GT(d.couplingAngularStiffness, 0.0);
  EXPECT_GE(d.couplingAngularDamping, 0.0);
}

TEST_F(Coupling, BadDefsAreRefusedByName) {
  proxBodyId body{};
  proxBodyDef d = tool_def(0.03);
  std::memcpy(&d.toolMode, "\x07\x00\x00\x00", 4);
  EXPECT_FAILS(proxWorld_CreateBody(world_, &d, &body), PROX_ERROR_INVALID_ARGUMENT, "toolMode");
  d = tool_def(0.03);
  d.type = PROX_BODY_MOVABLE;
  EXPECT_FAILS(proxWorld_CreateBody(world_, &d, &body), PROX_ERROR_INVALID_ARGUMENT, "PROX_BODY_TOOL");
  d = tool_def(0.03);
  d.couplingStiffness = 0.0;
  EXPECT_FAILS(proxWorld_CreateBody(world_, &d, &body), PROX_ERROR_INVALID_ARGUMENT, "couplingStiffness");
  d = tool_def(0.03);
  d.couplingDamping = NAN;
  EXPECT_FAILS(proxWorld_CreateBody(world_, &d, &body), PROX_ERROR_INVALID_ARGUMENT, "couplingDamping");
  d = tool_def(0.03);
  d.couplingAngularStiffness = INFINITY;
  EXPECT_FAILS(proxWorld_CreateBody(world_, &d, &body), PROX_ERROR_INVALID_ARGUMENT,
               "couplingAngularStiffness");
  d = tool_def(0.03);
  d.couplingAngularDamping = -1.0;
  EXPECT_FAILS(proxWorld_CreateBody(world_, &d, &body), PROX_ERROR_INVALID_ARGUMENT,
               "couplingAngularDamping");
  EXPECT_EQ(body.index1, 0u);
  proxPose pose;
  EXPECT_FAILS(proxBody_GetProxyPose(obstacle_, &pose), PROX_ERROR_INVALID_ARGUMENT, "tool");
  d = tool_def(0.03);
  ASSERT_OK(proxWorld_CreateBody(world_, &d, &body));
  EXPECT_FAILS(proxBody_GetProxyPose(body, nullptr), PROX_ERROR_INVALID_ARGUMENT, "pose");
}

TEST_F(Coupling, AFreeToolsProxyIsItsPose) {
  proxBodyDef d = tool_def(0.01);  // across A's face: a free tool goes where it is put
  d.toolMode = PROX_TOOL_FREE;
  proxBodyId tool{};
  ASSERT_OK(proxWorld_CreateBody(world_, &d, &tool));
  ASSERT_OK(proxWorld_Step(world_));
  proxPose pose, proxy;
  ASSERT_OK(proxBody_GetPose(tool, &pose));
  ASSERT_OK(proxBody_GetProxyPose(tool, &proxy));
  EXPECT_EQ(std::memcmp(&pose, &proxy, sizeof pose), 0);
  double distance = -1.0;
  ASSERT_OK(proxBody_GetDistance(obstacle_, tool, INFINITY, &distance));
  EXPECT_EQ(distance, 0.0);
}

TEST_F(Coupling, PushedInTheProxyStaysOutAndTheCouplingPullsBack) {
  const proxBodyDef d = tool_def(0.02);  // 5 mm clear of A along +x
  proxBodyId tool{};
  ASSERT_OK(proxWorld_CreateBody(world_, &d, &tool));
  // The device 8 mm into A, 0.1 mm a step, then held there.
  proxPose device = d.pose;
  double largest_force = 0.0;
  for (int i = 0; i < 200; ++i) {
    device.position.x = std::max(0.007, 0.02 - 0.0001 * i);
    ASSERT_OK(proxBody_SetPose(tool, &device));
    ASSERT_OK(proxWorld_Step(world_));
    double distance = -1.0;
    ASSERT_OK(proxBody_GetDistance(obstacle_, tool, INFINITY, &distance));
    ASSERT_GE(distance, safety_ * (1.0 - 1e-6)) << "step " << i;
    proxWrench w;
    ASSERT_OK(proxBody_GetWrench(tool, &w));
    largest_force = std::max(
        largest_force, std::sqrt(w.force.x * w.force.x + w.force.y * w.force.y + w.force.z * w.force.z));
    if (device.position.x < 0.014) {
      EXPECT_GT(w.force.x, 0.0) << "step " << i;  // out of A, along +x
    }
  }
  EXPECT_LE(largest_force, max_force_ * (1.0 + 1e-12));
  EXPECT_GT(largest_force, 1.0);
  proxPose pose, proxy;
  ASSERT_OK(proxBody_GetPose(tool, &pose));
  ASSERT_OK(proxBody_GetProxyPose(tool, &proxy));
  EXPECT_EQ(pose.position.x, 0.007);             // GetPose: the device
  EXPECT_GT(proxy.position.x, 0.015 + safety_);  // the proxy: outside A's face at x = 0.01
  EXPECT_LT(proxy.position.x, 0.015 + 3.0 * safety_);
  int32_t count = 0;
  const proxResult r = proxBody_GetContacts(tool, nullptr, 0, &count);
  EXPECT_TRUE(r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY);
  EXPECT_GT(count, 0);  // the proxy's contacts
}

}  // namespace
