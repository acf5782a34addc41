// proxWorldDef.workerCount: the game thread's own heavy work split over a
// pool, with answers that are the same bits as one thread's.
#include "expect.h"
#include "sheets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace capi_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Workers, TheCountIsCheckedAndDefaultsToOne) {
  EXPECT_EQ(proxDefaultWorldDef().workerCount, 1);
  proxWorldDef def = proxDefaultWorldDef();
  proxWorldId w{};
  for (int32_t bad : {0, -1, 257}) {
    def.workerCount = bad;
    EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_INVALID_ARGUMENT, "workerCount");
    EXPECT_FALSE(proxWorld_IsValid(w));
  }
  def.workerCount = 256;
  ASSERT_OK(proxCreateWorld(&def, &w));
  EXPECT_OK(proxWorld_Destroy(w));
}

// One world's scene: a 16,200-triangle sheet (large enough to be split)
// under a travelling wave, a small sheet held 1 mm above its middle.
struct Scene {
  proxWorldId world{};
  proxMeshId floor{};
  proxBodyId tool{};
  Sheet big{90, 0.2, false}, small{6, 0.02, true};

  explicit Scene(int32_t workers) {
    proxWorldDef def = proxDefaultWorldDef();
    def.workerCount = workers;
    EXPECT_OK(proxCreateWorld(&def, &world));
    const proxMeshDef floor_def = big.def(), tool_def = small.def();
    proxMeshId tool_mesh{};
    EXPECT_OK(proxWorld_CreateMesh(world, &floor_def, &floor));
    EXPECT_OK(proxWorld_CreateMesh(world, &tool_def, &tool_mesh));
    proxBodyDef body = proxDefaultBodyDef();
    body.mesh = floor;
    body.type = PROX_BODY_STATIC;
    proxBodyId floor_body{};
    EXPECT_OK(proxWorld_CreateBody(world, &body, &floor_body));
    body.mesh = tool_mesh;
    body.type = PROX_BODY_TOOL;
    // Tilted a little, so that no flat field ties its LMDs exactly.
    const double half = 0.5 * 0.03;
    body.pose.rotation = {std::cos(half), std::sin(half), 0.0, 0.0};
    body.pose.position = {0.09, 0.09, 0.003};
    EXPECT_OK(proxWorld_CreateBody(world, &body, &tool));
  }
  ~Scene() { EXPECT_OK(proxWorld_Destroy(world)); }

  // Frame f of the wave, then a step; the tool's contacts.
  std::vector<proxContact> frame(int f) {
    std::vector<double> moved = big.positions;
    for (std::size_t v = 0; v < moved.size(); v += 3)
      moved[v + 2] = 0.002 * std::sin(2.0 * kPi * (moved[v] / 0.05 - f / 60.0));
    EXPECT_OK(proxMesh_SetVertices(floor, moved.data(), static_cast<uint32_t>(moved.size() / 3)));
    EXPECT_OK(proxWorld_Step(world));
    int32_t count = 0;
    proxBody_GetContacts(tool, nullptr, 0, &count);
    std::vector<proxContact> contacts(static_cast<std::size_t>(count));
    EXPECT_OK(proxBody_GetContacts(tool, contacts.data(), count, &count));
    return contacts;
  }
};

TEST(Workers, ADeformingSceneStepsToTheSameBitsOnOneThreadAndOnThree) {
  Scene one(1), three(3);
  int compared = 0;
  for (int f = 0; f < 8; ++f) {
    const std::vector<proxContact> a = one.frame(f), b = three.frame(f);
    ASSERT_EQ(a.size(), b.size()) << "frame " << f;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].distance, b[i].distance) << "frame " << f << " contact " << i;
      EXPECT_EQ(a[i].triangleTool, b[i].triangleTool) << "frame " << f << " contact " << i;
      EXPECT_EQ(a[i].triangleOther, b[i].triangleOther) << "frame " << f << " contact " << i;
      EXPECT_EQ(std::memcmp(&a[i].pointOther, &b[i].pointOther, sizeof(proxVec3)), 0)
          << "frame " << f << " contact " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 8) << "the tool is in contact in every frame";
}

}  // namespace
}  // namespace capi_test
