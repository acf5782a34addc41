// The C API of patches and intersections (docs/patches.md): the rule's
// defaults and checks, what a step merged, and crossing surfaces reported as
// an intersection rather than as contacts.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "sheets.h"

#include <cmath>
#include <vector>

namespace {

using capi_test::Sheet;

class Patches : public ::testing::Test {
 protected:
  void SetUp() override {
    proxWorldDef def = proxDefaultWorldDef();  // cutoff 5 mm
    ASSERT_OK(proxCreateWorld(&def, &world));
    const Sheet up(20, 0.02, false), down(20, 0.02, true);
    const proxMeshDef du = up.def(), dd = down.def();
    ASSERT_OK(proxWorld_CreateMesh(world, &du, &floor_mesh));
    ASSERT_OK(proxWorld_CreateMesh(world, &dd, &tool_mesh));
    proxBodyDef b = proxDefaultBodyDef();
    b.mesh = floor_mesh;
    b.type = PROX_BODY_STATIC;
    ASSERT_OK(proxWorld_CreateBody(world, &b, &floor));
    b.mesh = tool_mesh;
    b.type = PROX_BODY_TOOL;
    b.pose = {{0.0, 0.0, 0.001}, {1, 0, 0, 0}};  // 1 mm above, facing it
    ASSERT_OK(proxWorld_CreateBody(world, &b, &tool));
  }
  void TearDown() override {
    if (proxWorld_IsValid(world)) EXPECT_OK(proxDestroyWorld(world));
  }
  int32_t contact_count() {
    int32_t n = 0;
    const proxResult r = proxBody_GetContacts(tool, nullptr, 0, &n);
    EXPECT_TRUE(r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY);
    return n;
  }
  proxWorldId world{};
  proxMeshId floor_mesh{}, tool_mesh{};
  proxBodyId floor{}, tool{};
};

TEST_F(Patches, SettingsHaveDefaultsAndAreChecked) {
  proxPatchSettings s{};
  ASSERT_OK(proxWorld_GetPatchSettings(world, &s));
  EXPECT_EQ(s.radiusOverCutoff, 1.0);
  EXPECT_EQ(s.maxAngleDegrees, 5.0);
  EXPECT_EQ(s.maxSpreadOverCutoff, 0.002);
  EXPECT_FAILS(proxWorld_GetPatchSettings(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "settings is NULL");
  EXPECT_FAILS(proxWorld_SetPatchSettings(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "settings is NULL");
  proxPatchSettings bad = s;
  bad.radiusOverCutoff = -0.5;
  EXPECT_FAILS(proxWorld_SetPatchSettings(world, &bad), PROX_ERROR_INVALID_ARGUMENT, "radiusOverCutoff");
  bad.radiusOverCutoff = NAN;
  EXPECT_FAILS(proxWorld_SetPatchSettings(world, &bad), PROX_ERROR_INVALID_ARGUMENT, "radiusOverCutoff");
  bad = s;
  bad.maxAngleDegrees = 181.0;
  EXPECT_FAILS(proxWorld_SetPatchSettings(world, &bad), PROX_ERROR_INVALID_ARGUMENT, "maxAngleDegrees");
  bad = s;
  bad.maxSpreadOverCutoff = -1.0;
  EXPECT_FAILS(proxWorld_SetPatchSettings(world, &bad), PROX_ERROR_INVALID_ARGUMENT, "maxSpreadOverCutoff");
  EXPECT_FAILS(proxWorld_SetPatchSettings(proxWorldId{}, &s), PROX_ERROR_INVALID_HANDLE, "null");
  proxPatchStats st;
  EXPECT_FAILS(proxWorld_GetPatchStats(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats is NULL");
  ASSERT_OK(proxWorld_GetPatchStats(world, &st));  // zeros before the first step
  EXPECT_EQ(st.lmds, 0);
  const proxPatchSettings changed{0.5, 2.0, 0.01};
  ASSERT_OK(proxWorld_SetPatchSettings(world, &changed));
  ASSERT_OK(proxWorld_GetPatchSettings(world, &s));
  EXPECT_EQ(s.radiusOverCutoff, 0.5);
  EXPECT_EQ(s.maxAngleDegrees, 2.0);
}

TEST_F(Patches, ParallelSheetsMergeAndTheRuleCanBeTurnedOff) {
  ASSERT_OK(proxWorld_Step(world));
  proxPatchStats merged;
  ASSERT_OK(proxWorld_GetPatchStats(world, &merged));
  // 2 cm sheets, 1 mm apart, every triangle pair over the other a local
  // minimum; seeds more than 5 mm apart: at most (2 + 0.5)^2 / (pi 0.5^2 / 4) = 31.
  EXPECT_GT(merged.lmds, 800);
  EXPECT_LE(merged.patches, 31);
  EXPECT_EQ(merged.merged, merged.lmds - merged.patches);
  EXPECT_GT(merged.largestPatch, 1);
  EXPECT_EQ(contact_count(), merged.patches);
  EXPECT_EQ(merged.intersectingPairs, 0u);
  EXPECT_EQ(merged.intersectingBodies, 0);
  proxWrench w_merged;
  ASSERT_OK(proxBody_GetWrench(tool, &w_merged));

  const proxPatchSettings off{0.0, 5.0, 0.002};
  ASSERT_OK(proxWorld_SetPatchSettings(world, &off));
  ASSERT_OK(proxWorld_Step(world));  // the pose did not move: the setting alone makes it search again
  proxPatchStats unmerged;
  ASSERT_OK(proxWorld_GetPatchStats(world, &unmerged));
  EXPECT_EQ(unmerged.lmds, merged.lmds);
  EXPECT_EQ(unmerged.patches, unmerged.lmds);
  EXPECT_EQ(unmerged.merged, 0);
  EXPECT_EQ(contact_count(), unmerged.lmds);
  // Parallel sheets: every LMD pushes straight up at the same distance, so
  // the patches' force is the unmerged one (both at the clip).
  proxWrench w_unmerged;
  ASSERT_OK(proxBody_GetWrench(tool, &w_unmerged));
  EXPECT_NEAR(w_merged.force.z, w_unmerged.force.z, 1e-9);
  EXPECT_GT(w_merged.force.z, 0.0);
}

TEST_F(Patches, CrossingSheetsAreAnIntersectionNotContacts) {
  // The tool turned upright (90 degrees about x) and pushed through the
  // floor along its middle.
  const double h = std::sqrt(0.5);
  const proxPose through{{0.0, 0.01, -0.01}, {h, h, 0.0, 0.0}};
  ASSERT_OK(proxBody_SetPose(tool, &through));
  ASSERT_OK(proxWorld_Step(world));
  proxPatchStats s;
  ASSERT_OK(proxWorld_GetPatchStats(world, &s));
  // Some crossing pairs reach the search's exact test (the cone tests may
  // cull others before it): never more than the polylines' exact count.
  EXPECT_GE(s.intersectingPairs, 1u);
  EXPECT_EQ(s.intersectingBodies, 1);
  std::vector<proxContact> contacts(static_cast<size_t>(contact_count()));
  int32_t n = 0;
  ASSERT_OK(proxBody_GetContacts(tool, contacts.data(), static_cast<int32_t>(contacts.size()), &n));
  for (const proxContact& c : contacts) EXPECT_GT(c.distance, 0.0);  // none at the crossing itself
  int32_t points = 0, lines = 0;
  EXPECT_EQ(proxBody_GetIntersections(tool, nullptr, 0, &points, nullptr, 0, &lines), PROX_ERROR_CAPACITY);
  EXPECT_GE(lines, 1);
  proxIntersectionStats exact;
  ASSERT_OK(proxBody_GetIntersectionStats(tool, &exact));
  EXPECT_LE(s.intersectingPairs, exact.intersectingPairs);
  // Apart again: no intersection.
  const proxPose above{{0.0, 0.0, 0.001}, {1, 0, 0, 0}};
  ASSERT_OK(proxBody_SetPose(tool, &above));
  ASSERT_OK(proxWorld_Step(world));
  ASSERT_OK(proxWorld_GetPatchStats(world, &s));
  EXPECT_EQ(s.intersectingPairs, 0u);
  EXPECT_EQ(s.intersectingBodies, 0);
}

}  // namespace
