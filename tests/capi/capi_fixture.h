// The C API tests' fixture: a world (cutoff 5 cm) with a unit cube's mesh, bodies made
// from it, and a unit cube's arrays (capi_test.cpp, inspection_capi_test.cpp).
#pragma once

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "mesh_arrays.h"

#include <cstdint>
#include <vector>

namespace capi_fixture {

// A unit cube (8 vertices, 12 triangles) scaled by `s`.
struct Cube {
  std::vector<double> positions;
  std::vector<uint32_t> indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  explicit Cube(double s = 1.0) {
    const double p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    for (double x : p) positions.push_back(x * s);
  }
  proxMeshDef def() const { return capi_test::mesh_def(positions, indices); }
};

inline proxPose at(double x, double y = 0, double z = 0) { return {{x, y, z}, {1, 0, 0, 0}}; }

class CApi : public ::testing::Test {
 protected:
  void SetUp() override {
    proxWorldDef def = proxDefaultWorldDef();
    def.cutoff = 0.05;
    def.force.safetyDistance = 0.001;
    ASSERT_OK(proxCreateWorld(&def, &world));
    const proxMeshDef md = cube.def();
    ASSERT_OK(proxWorld_CreateMesh(world, &md, &mesh));
  }
  void TearDown() override {
    if (proxWorld_IsValid(world)) EXPECT_OK(proxWorld_Destroy(world));
  }
  proxBodyId body(proxBodyType type, const proxPose& pose) {
    proxBodyDef d = proxDefaultBodyDef();
    d.mesh = mesh;
    d.type = type;
    d.pose = pose;
    proxBodyId id{};
    EXPECT_OK(proxWorld_CreateBody(world, &d, &id));
    return id;
  }
  Cube cube;
  proxWorldId world{};
  proxMeshId mesh{};
};

}  // namespace capi_fixture
