// The scene of the C API's timing tests: one world holding a lone tool (a
// 10 cm triangle, 1 m out), nothing for it to touch, so the threads' loops
// run on nothing but their own pacing.
#pragma once

#include "expect.h"
#include "two_cubes.h"

#include <proxima/proxima.h>

#include <gtest/gtest.h>

namespace capi_test {

class LoneTool : public ::testing::Test {
 protected:
  void SetUp() override {
    const proxWorldDef def = proxDefaultWorldDef();
    ASSERT_OK(proxCreateWorld(&def, &world));
    const double p[] = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0};
    const uint32_t tri[] = {0, 1, 2};
    proxMeshDef md = proxDefaultMeshDef();
    md.positions = p;
    md.vertexCount = 3;
    md.indices = tri;
    md.triangleCount = 1;
    ASSERT_OK(proxWorld_CreateMesh(world, &md, &mesh));
    proxBodyDef bd = proxDefaultBodyDef();
    bd.mesh = mesh;
    bd.type = PROX_BODY_TOOL;
    bd.pose = at(1.0);
    ASSERT_OK(proxWorld_CreateBody(world, &bd, &tool));
  }
  void TearDown() override {
    if (proxWorld_IsValid(world)) EXPECT_OK(proxWorld_Destroy(world));
  }

  proxWorldId world{};
  proxMeshId mesh{};
  proxBodyId tool{};
};

}  // namespace capi_test
