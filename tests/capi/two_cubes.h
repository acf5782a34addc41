// The scene of the C API's threaded tests: two 10 cm cubes, the wall static
// at the origin and the tool beside it along +x, with a 10 mm cutoff, and
// what those tests share (poses along x, waiting for a condition).
#pragma once

#include "expect.h"
#include "mesh_arrays.h"

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

namespace capi_test {

inline proxPose at(double x, double y = 0, double z = 0) { return {{x, y, z}, {1, 0, 0, 0}}; }
inline double length(const proxVec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// Polls `done` every 2 ms for up to `seconds`; its last answer.
inline bool wait_until(const std::function<bool()>& done, double seconds = 60.0) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

class TwoCubes : public ::testing::Test {
 protected:
  // The world (safety distance 1 mm, decay 2 mm), the wall, and the tool at
  // x = tool_x (its reference point the cube's centre). Call from SetUp and
  // check with ASSERT_NO_FATAL_FAILURE.
  void create_scene(double tool_x) {
    proxWorldDef def = proxDefaultWorldDef();
    def.cutoff = 0.01;
    def.force.safetyDistance = 0.001;
    def.force.decayLength = 0.002;
    ASSERT_OK(proxCreateWorld(&def, &world));
    max_force = def.force.maxForce;
    const double corners[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    positions.clear();
    for (const double c : corners) positions.push_back(0.1 * c);
    const proxMeshDef md = mesh_def(positions, indices);
    ASSERT_OK(proxWorld_CreateMesh(world, &md, &mesh));
    proxBodyDef bd = proxDefaultBodyDef();
    bd.mesh = mesh;
    ASSERT_OK(proxWorld_CreateBody(world, &bd, &wall));
    bd.type = PROX_BODY_TOOL;
    bd.pose = at(tool_x);
    bd.referencePoint = {0.05, 0.05, 0.05};
    ASSERT_OK(proxWorld_CreateBody(world, &bd, &tool));
  }
  void TearDown() override {
    if (proxWorld_IsValid(world)) EXPECT_OK(proxWorld_Destroy(world));
  }

  // The cube's 8 corners and 12 triangles, for another mesh like it.
  std::vector<double> positions;
  std::vector<uint32_t> indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  proxWorldId world{};
  proxMeshId mesh{};
  proxBodyId wall{}, tool{};
  double max_force = 0.0;
};

}  // namespace capi_test
