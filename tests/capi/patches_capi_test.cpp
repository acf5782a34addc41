// The C API of patches and intersections (docs/patches.md): the rule's
// defaults and checks, what a step merged, and crossing surfaces reported as
// an intersection rather than as contacts.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "sheets.h"

#include <algorithm>
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
    if (proxWorld_IsValid(world)) EXPECT_OK(proxWorld_Destroy(world));
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

// Each contact's patch, beside the contact from one snapshot: the counts add
// up to the LMDs the step found before merging, and every patch keeps the
// rule (radius, spread, angle); with merging off every contact stands alone.
TEST_F(Patches, EachContactSaysWhatItsPatchHolds) {
  ASSERT_OK(proxWorld_Step(world));
  proxPatchStats stats;
  ASSERT_OK(proxWorld_GetPatchStats(world, &stats));
  const int32_t n = contact_count();
  ASSERT_EQ(n, stats.patches);
  std::vector<proxContact> contacts(static_cast<size_t>(n)), beside(static_cast<size_t>(n));
  std::vector<proxContactPatch> patches(static_cast<size_t>(n));
  int32_t count = 0;
  ASSERT_OK(proxBody_GetContacts(tool, contacts.data(), n, &count));
  ASSERT_OK(proxBody_GetContactPatches(tool, beside.data(), patches.data(), n, &count));
  ASSERT_EQ(count, n);
  const double cutoff = 0.005, kRounding = 1e-12;
  long long total = 0;
  int32_t largest = 0;
  for (size_t i = 0; i < patches.size(); ++i) {
    const proxContactPatch& p = patches[i];
    // The same contacts, in the same order, as proxBody_GetContacts gives.
    EXPECT_EQ(beside[i].triangleTool, contacts[i].triangleTool) << i;
    EXPECT_EQ(beside[i].triangleOther, contacts[i].triangleOther) << i;
    EXPECT_EQ(beside[i].distance, contacts[i].distance) << i;
    EXPECT_GE(p.count, 1) << i;
    EXPECT_EQ(p.reserved, 0);
    total += p.count;
    largest = std::max(largest, p.count);
    // A merged member's point on the tool is within the radius (the cutoff)
    // of its seed's, at most the spread farther, within 5 degrees.
    EXPECT_GE(p.extent, 0.0);
    EXPECT_LE(p.extent, 1.0 * cutoff + kRounding) << i;
    EXPECT_GE(p.spread, 0.0);
    EXPECT_LE(p.spread, 0.002 * cutoff + kRounding) << i;
    EXPECT_GE(p.angle, 0.0);
    EXPECT_LE(p.angle, 5.0 * 3.14159265358979323846 / 180.0 + 1e-9) << i;
    if (p.count == 1) {
      EXPECT_EQ(p.extent, 0.0) << i;
    }
  }
  EXPECT_EQ(total, stats.lmds);
  EXPECT_EQ(largest, stats.largestPatch);
  EXPECT_GT(largest, 1);

  // Only the patches; then too small a buffer: what fits, and the count.
  std::vector<proxContactPatch> only(static_cast<size_t>(n));
  ASSERT_OK(proxBody_GetContactPatches(tool, nullptr, only.data(), n, &count));
  for (size_t i = 0; i < only.size(); ++i) EXPECT_EQ(only[i].count, patches[i].count) << i;
  std::vector<proxContactPatch> two(2);
  EXPECT_FAILS(proxBody_GetContactPatches(tool, nullptr, two.data(), 2, &count), PROX_ERROR_CAPACITY,
               "capacity 2");
  EXPECT_EQ(count, n);
  EXPECT_EQ(two[1].count, patches[1].count);

  const proxPatchSettings off{0.0, 5.0, 0.002};
  ASSERT_OK(proxWorld_SetPatchSettings(world, &off));
  ASSERT_OK(proxWorld_Step(world));
  const int32_t unmerged = contact_count();
  std::vector<proxContactPatch> single(static_cast<size_t>(unmerged));
  ASSERT_OK(proxBody_GetContactPatches(tool, nullptr, single.data(), unmerged, &count));
  ASSERT_EQ(count, total);
  for (const proxContactPatch& p : single) {
    EXPECT_EQ(p.count, 1);
    EXPECT_EQ(p.extent, 0.0);
    EXPECT_EQ(p.spread, 0.0);
    EXPECT_EQ(p.angle, 0.0);
  }
}

TEST_F(Patches, ContactPatchesRefuseMisuseByName) {
  ASSERT_OK(proxWorld_Step(world));
  int32_t count = -1;
  proxContactPatch p[2];
  EXPECT_FAILS(proxBody_GetContactPatches(tool, nullptr, p, 2, nullptr), PROX_ERROR_INVALID_ARGUMENT,
               "count is NULL");
  EXPECT_FAILS(proxBody_GetContactPatches(tool, nullptr, p, -1, &count), PROX_ERROR_INVALID_ARGUMENT,
               "negative");
  EXPECT_FAILS(proxBody_GetContactPatches(tool, nullptr, nullptr, 2, &count), PROX_ERROR_INVALID_ARGUMENT,
               "both NULL");
  EXPECT_FAILS(proxBody_GetContactPatches(floor, nullptr, nullptr, 0, &count), PROX_ERROR_INVALID_ARGUMENT,
               "PROX_BODY_TOOL");
  EXPECT_FAILS(proxBody_GetContactPatches(proxBodyId{}, nullptr, nullptr, 0, &count),
               PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_EQ(proxBody_GetContactPatches(tool, nullptr, nullptr, 0, &count), PROX_ERROR_CAPACITY);
  EXPECT_EQ(count, contact_count());
}

// The bounded search's budget: its default and checks, kept when the patch
// rule changes; past it the search cuts node pairs of patch size and says
// how many; the closest contact and the clipped force of the flat sheets
// are unchanged.
TEST_F(Patches, TheLeafBudgetCutsTheSearchAndSaysSo) {
  uint64_t budget = 0;
  ASSERT_OK(proxWorld_GetLeafBudget(world, &budget));
  EXPECT_EQ(budget, 50000u);
  EXPECT_FAILS(proxWorld_GetLeafBudget(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "leafPairs is NULL");
  EXPECT_FAILS(proxWorld_SetLeafBudget(proxWorldId{}, 5), PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_FAILS(proxWorld_GetLeafBudget(proxWorldId{}, &budget), PROX_ERROR_INVALID_HANDLE, "null");
  ASSERT_OK(proxWorld_Step(world));
  proxPatchStats whole;
  proxSearchStats whole_search;
  ASSERT_OK(proxWorld_GetPatchStats(world, &whole));
  ASSERT_OK(proxWorld_GetSearchStats(world, &whole_search));
  EXPECT_EQ(whole.cutNodePairs, 0);
  proxWrench whole_force;
  ASSERT_OK(proxBody_GetWrench(tool, &whole_force));

  ASSERT_OK(proxWorld_SetLeafBudget(world, 50));
  proxPatchSettings rule;
  ASSERT_OK(proxWorld_GetPatchSettings(world, &rule));
  ASSERT_OK(proxWorld_SetPatchSettings(world, &rule));
  ASSERT_OK(proxWorld_GetLeafBudget(world, &budget));
  EXPECT_EQ(budget, 50u) << "the patch rule leaves the budget alone";
  ASSERT_OK(proxWorld_Step(world));  // the setting alone makes it search again
  proxPatchStats cut;
  proxSearchStats cut_search;
  ASSERT_OK(proxWorld_GetPatchStats(world, &cut));
  ASSERT_OK(proxWorld_GetSearchStats(world, &cut_search));
  EXPECT_GT(cut.cutNodePairs, 0);
  // At most 8 triangle pairs are tried for each node pair cut.
  EXPECT_LE(cut_search.leafPairs, 50u + 8u * static_cast<uint64_t>(cut.cutNodePairs));
  EXPECT_LT(cut_search.leafPairs, whole_search.leafPairs);
  EXPECT_LT(cut.lmds, whole.lmds) << "the cut LMDs are not counted";
  const int32_t n = contact_count();
  ASSERT_GE(n, 1);
  std::vector<proxContact> contacts(static_cast<size_t>(n));
  int32_t count = 0;
  ASSERT_OK(proxBody_GetContacts(tool, contacts.data(), n, &count));
  for (const proxContact& c : contacts) {  // flat and parallel: every contact 1 mm, straight up
    EXPECT_NEAR(c.distance, 0.001, 1e-12);
    EXPECT_NEAR(c.normal.z, 1.0, 1e-12);
  }
  // Both sums are far beyond the clip, straight up.
  proxWrench cut_force;
  ASSERT_OK(proxBody_GetWrench(tool, &cut_force));
  EXPECT_TRUE(cut_force.clipped && whole_force.clipped);
  EXPECT_NEAR(cut_force.force.z, whole_force.force.z, 1e-9);
  EXPECT_NEAR(cut_force.force.x, 0.0, 1e-9);

  ASSERT_OK(proxWorld_SetLeafBudget(world, 0));  // no bound
  ASSERT_OK(proxWorld_Step(world));
  ASSERT_OK(proxWorld_GetPatchStats(world, &cut));
  EXPECT_EQ(cut.cutNodePairs, 0);
  EXPECT_EQ(cut.lmds, whole.lmds);
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
