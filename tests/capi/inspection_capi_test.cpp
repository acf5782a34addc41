// The C API's inspection surface (proxima/inspect.h): force presets, mesh
// and search statistics, the reference method, tracking, intersection
// statistics, distances, and its thread rule.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "capi_fixture.h"
#include "expect.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace capi_fixture;

// ---- inspection -------------------------------------------------------------------

TEST(CApiInspection, ForcePresets) {
  proxForceSettings f{};
  double cutoff = 0.0;
  EXPECT_FAILS(proxGetForcePreset(PROX_FORCE_PRESET_HARD, nullptr, &cutoff), PROX_ERROR_INVALID_ARGUMENT,
               "force is NULL");
  EXPECT_FAILS(proxGetForcePreset(PROX_FORCE_PRESET_HARD, &f, nullptr), PROX_ERROR_INVALID_ARGUMENT,
               "cutoff is NULL");
  EXPECT_FAILS(proxGetForcePreset(static_cast<proxForcePreset>(2), &f, &cutoff), PROX_ERROR_INVALID_ARGUMENT,
               "preset");
  // Hard is the default world def's.
  ASSERT_OK(proxGetForcePreset(PROX_FORCE_PRESET_HARD, &f, &cutoff));
  const proxWorldDef def = proxDefaultWorldDef();
  EXPECT_EQ(cutoff, def.cutoff);
  EXPECT_EQ(f.curve, def.force.curve);
  EXPECT_EQ(f.maxForce, def.force.maxForce);
  EXPECT_EQ(f.maxTorque, def.force.maxTorque);
  EXPECT_EQ(f.safetyDistance, def.force.safetyDistance);
  EXPECT_EQ(f.decayLength, def.force.decayLength);
  // Soft, from any thread; and a world takes it as it is.
  proxResult r = PROX_ERROR_INTERNAL;
  std::thread([&] { r = proxGetForcePreset(PROX_FORCE_PRESET_SOFT, &f, &cutoff); }).join();
  ASSERT_EQ(r, PROX_SUCCESS);
  EXPECT_EQ(f.curve, PROX_FORCE_LINEAR);
  EXPECT_DOUBLE_EQ(f.safetyDistance, 0.002);
  EXPECT_DOUBLE_EQ(cutoff, 0.01);
  proxWorldDef soft = proxDefaultWorldDef();
  soft.force = f;
  soft.cutoff = cutoff;
  proxWorldId w{};
  ASSERT_OK(proxCreateWorld(&soft, &w));
  EXPECT_OK(proxWorld_Destroy(w));
}

TEST_F(CApi, MeshStats) {
  proxMeshStats s;
  EXPECT_FAILS(proxMesh_GetStats(mesh, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats is NULL");
  EXPECT_FAILS(proxMesh_GetStats(proxMeshId{}, &s), PROX_ERROR_INVALID_HANDLE, "null");
  ASSERT_OK(proxMesh_GetStats(mesh, &s));
  EXPECT_EQ(s.inputVertices, 8u);
  EXPECT_EQ(s.inputTriangles, 12u);
  EXPECT_EQ(s.zeroAreaTriangles, 0u);
  EXPECT_EQ(s.hierarchyLeaves, 12u);  // one triangle per leaf
  EXPECT_EQ(s.hierarchyNodes, 23u);   // a binary tree over 12 leaves
  EXPECT_GE(s.hierarchyDepth, 4u);
  EXPECT_GT(s.hierarchyBytes, 0u);
  EXPECT_GE(s.hierarchySeconds, 0.0);
  // Welding shows: a square given as two triangles with their own vertices.
  const double p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint32_t i[] = {0, 1, 2, 3, 4, 5};
  proxMeshDef d = proxDefaultMeshDef();
  d.positions = p, d.vertexCount = 6, d.indices = i, d.triangleCount = 2;
  proxMeshId square{};
  ASSERT_OK(proxWorld_CreateMesh(world, &d, &square));
  ASSERT_OK(proxMesh_GetStats(square, &s));
  EXPECT_EQ(s.inputVertices, 6u);
  proxMeshInfo info;
  ASSERT_OK(proxMesh_GetInfo(square, &info));
  EXPECT_EQ(info.vertexCount, 4u);
  ASSERT_OK(proxMesh_Destroy(square));
  EXPECT_FAILS(proxMesh_GetStats(square, &s), PROX_ERROR_INVALID_HANDLE, "live mesh");
}

TEST_F(CApi, SearchStatsOfTheLastStep) {
  proxSearchStats s;
  EXPECT_FAILS(proxWorld_GetSearchStats(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats is NULL");
  EXPECT_FAILS(proxWorld_GetSearchStats(proxWorldId{}, &s), PROX_ERROR_INVALID_HANDLE, "null");
  ASSERT_OK(proxWorld_GetSearchStats(world, &s));  // before any step: nothing
  EXPECT_EQ(s.pairsSearched, 0);
  EXPECT_EQ(s.nodePairs, 0u);
  body(PROX_BODY_STATIC, at(0));
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0, 0, 1.01));
  ASSERT_OK(proxWorld_Step(world));
  ASSERT_OK(proxWorld_GetSearchStats(world, &s));
  int32_t count = 0;
  EXPECT_EQ(proxBody_GetContacts(tool, nullptr, 0, &count), PROX_ERROR_CAPACITY);
  proxWorldStats w;
  ASSERT_OK(proxWorld_GetStats(world, &w));
  EXPECT_EQ(s.pairsSearched, 1);
  EXPECT_GT(s.nodePairs, 0u);
  EXPECT_GT(s.leafPairs, 0u);
  EXPECT_GT(s.distanceEvaluations, 0u);
  EXPECT_EQ(s.normalRejections, 0u);  // the precise method has no G5 check
  EXPECT_EQ(s.candidates, static_cast<uint64_t>(w.candidates));
  EXPECT_GE(s.candidates, static_cast<uint64_t>(count));
  EXPECT_GE(s.globalSeconds, 0.0);
  EXPECT_GE(s.reductionSeconds, 0.0);
  // Nothing moved: no search, nothing counted.
  ASSERT_OK(proxWorld_Step(world));
  ASSERT_OK(proxWorld_GetSearchStats(world, &s));
  EXPECT_EQ(s.pairsSearched, 0);
  EXPECT_EQ(s.nodePairs, 0u);
  EXPECT_EQ(s.candidates, 0u);
  ASSERT_OK(proxWorld_Destroy(world));
  EXPECT_FAILS(proxWorld_GetSearchStats(world, &s), PROX_ERROR_INVALID_HANDLE, "live world");
}

TEST(CApiInspection, TheReferenceMethodAgreesWithThePreciseOne) {
  // A triangle whose vertex hangs 2 mm over another's face.
  const double pa[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const double pb[] = {0.25, 0.25, 0.002, 1, 0.5, 1, 0.5, 1, 1};
  const uint32_t ia[] = {0, 1, 2}, ib[] = {0, 2, 1};
  double distance[2] = {0, 0};
  const proxMethod methods[2] = {PROX_METHOD_PRECISE, PROX_METHOD_REFERENCE};
  for (int m = 0; m < 2; ++m) {
    proxWorldDef def = proxDefaultWorldDef();
    def.method = methods[m];
    def.cutoff = 0.5;
    proxWorldId w{};
    ASSERT_OK(proxCreateWorld(&def, &w));
    proxMeshDef md = proxDefaultMeshDef();
    md.positions = pa, md.vertexCount = 3, md.indices = ia, md.triangleCount = 1;
    proxMeshId a{}, b{};
    ASSERT_OK(proxWorld_CreateMesh(w, &md, &a));
    md.positions = pb, md.indices = ib;
    ASSERT_OK(proxWorld_CreateMesh(w, &md, &b));
    proxBodyDef bd = proxDefaultBodyDef();
    bd.mesh = a;
    proxBodyId body{}, tool{};
    ASSERT_OK(proxWorld_CreateBody(w, &bd, &body));
    bd.mesh = b;
    bd.type = PROX_BODY_TOOL;
    ASSERT_OK(proxWorld_CreateBody(w, &bd, &tool));
    ASSERT_OK(proxWorld_Step(w));
    proxContact c[4];
    int32_t count = 0;
    ASSERT_OK(proxBody_GetContacts(tool, c, 4, &count));
    ASSERT_EQ(count, 1);
    EXPECT_EQ(c[0].featureTool, 0);   // B's vertex
    EXPECT_EQ(c[0].featureOther, 2);  // over A's face
    distance[m] = c[0].distance;
    EXPECT_OK(proxWorld_Destroy(w));
  }
  EXPECT_NEAR(distance[0], 0.002, 1e-12);
  EXPECT_EQ(distance[0], distance[1]);
}

TEST_F(CApi, TrackCarriesContactsToTheCurrentPoses) {
  proxTrackStats t;
  EXPECT_FAILS(proxWorld_Track(proxWorldId{}), PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_FAILS(proxWorld_GetTrackStats(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats is NULL");
  EXPECT_FAILS(proxWorld_GetTrackStats(proxWorldId{}, &t), PROX_ERROR_INVALID_HANDLE, "null");
  ASSERT_OK(proxWorld_GetTrackStats(world, &t));  // zeros before the first
  EXPECT_EQ(t.pairsTracked, 0);
  EXPECT_EQ(t.seconds, 0.0);
  const proxBodyId rock = body(PROX_BODY_STATIC, at(0));
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0, 0, 1.01));
  // Nothing stepped yet: nothing to track.
  ASSERT_OK(proxWorld_Track(world));
  ASSERT_OK(proxWorld_GetTrackStats(world, &t));
  EXPECT_EQ(t.pairsTracked, 0);
  ASSERT_OK(proxWorld_Step(world));
  int32_t before = 0;
  EXPECT_EQ(proxBody_GetContacts(tool, nullptr, 0, &before), PROX_ERROR_CAPACITY);
  proxWrench far{};
  ASSERT_OK(proxBody_GetWrench(tool, &far));
  // The tool comes 5 mm closer: tracking alone follows it, and the force grows.
  const proxPose closer = at(0, 0, 1.005);
  ASSERT_OK(proxBody_SetPose(tool, &closer));
  ASSERT_OK(proxWorld_Track(world));
  ASSERT_OK(proxWorld_GetTrackStats(world, &t));
  EXPECT_EQ(t.pairsTracked, 1);
  EXPECT_EQ(t.contactsIn, before);
  EXPECT_GE(t.contactsOut, 1);
  EXPECT_GT(t.distanceEvaluations + t.cacheHits, 0u);
  EXPECT_GE(t.seconds, 0.0);
  std::vector<proxContact> contacts(static_cast<std::size_t>(t.contactsOut));
  int32_t count = 0;
  ASSERT_OK(proxBody_GetContacts(tool, contacts.data(), t.contactsOut, &count));
  EXPECT_EQ(count, t.contactsOut);
  for (const proxContact& c : contacts) {
    EXPECT_NEAR(c.distance, 0.005, 1e-12);
    EXPECT_EQ(c.other.index1, rock.index1);
  }
  proxWrench near{};
  ASSERT_OK(proxBody_GetWrench(tool, &near));
  EXPECT_GT(near.force.z, far.force.z);
  // Out of the cutoff: tracking drops every contact, and the force is zero.
  const proxPose away = at(0, 0, 1.2);
  ASSERT_OK(proxBody_SetPose(tool, &away));
  ASSERT_OK(proxWorld_Track(world));
  ASSERT_OK(proxWorld_GetTrackStats(world, &t));
  EXPECT_EQ(t.contactsOut, 0);
  ASSERT_OK(proxBody_GetContacts(tool, nullptr, 0, &count));
  EXPECT_EQ(count, 0);
  ASSERT_OK(proxBody_GetWrench(tool, &near));
  EXPECT_EQ(near.force.z, 0.0);
  ASSERT_OK(proxWorld_Destroy(world));
  EXPECT_FAILS(proxWorld_Track(world), PROX_ERROR_INVALID_HANDLE, "live world");
  EXPECT_FAILS(proxWorld_GetTrackStats(world, &t), PROX_ERROR_INVALID_HANDLE, "live world");
}

TEST_F(CApi, IntersectionStats) {
  const proxBodyId rock = body(PROX_BODY_STATIC, at(0));
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0.5, 0.3, 0.4));
  proxIntersectionStats s;
  EXPECT_FAILS(proxBody_GetIntersectionStats(tool, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats is NULL");
  EXPECT_FAILS(proxBody_GetIntersectionStats(rock, &s), PROX_ERROR_INVALID_ARGUMENT, "PROX_BODY_TOOL");
  EXPECT_FAILS(proxBody_GetIntersectionStats(proxBodyId{}, &s), PROX_ERROR_INVALID_HANDLE, "null");
  ASSERT_OK(proxBody_GetIntersectionStats(tool, &s));  // zeros before the first call
  EXPECT_EQ(s.intersectingPairs, 0u);
  int32_t points = 0, lines = 0;
  EXPECT_EQ(proxBody_GetIntersections(tool, nullptr, 0, &points, nullptr, 0, &lines), PROX_ERROR_CAPACITY);
  ASSERT_OK(proxBody_GetIntersectionStats(tool, &s));
  // Each of the six crossing faces is two triangles: at least six pairs cross.
  EXPECT_GE(s.intersectingPairs, 6u);
  EXPECT_GE(s.trianglePairs, s.intersectingPairs);
  EXPECT_EQ(s.coplanarPairs, 0u);
  EXPECT_GE(s.segments, 6u);
  EXPECT_GE(s.seconds, 0.0);
  // Apart: the next call finds nothing, and says so.
  const proxPose away = at(3, 0, 0);
  ASSERT_OK(proxBody_SetPose(tool, &away));
  ASSERT_OK(proxBody_GetIntersections(tool, nullptr, 0, &points, nullptr, 0, &lines));
  ASSERT_OK(proxBody_GetIntersectionStats(tool, &s));
  EXPECT_EQ(s.intersectingPairs, 0u);
  EXPECT_EQ(s.segments, 0u);
  ASSERT_OK(proxBody_Destroy(tool));
  EXPECT_FAILS(proxBody_GetIntersectionStats(tool, &s), PROX_ERROR_INVALID_HANDLE, "live body");
}

TEST_F(CApi, DistanceBetweenTwoBodies) {
  const proxBodyId rock = body(PROX_BODY_STATIC, at(0));
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0, 0, 1.01));
  const proxBodyId far = body(PROX_BODY_MOVABLE, at(0, 0, 3));
  double d = 0.0;
  EXPECT_FAILS(proxBody_GetDistance(rock, tool, 1.0, nullptr), PROX_ERROR_INVALID_ARGUMENT,
               "distance is NULL");
  EXPECT_FAILS(proxBody_GetDistance(proxBodyId{}, tool, 1.0, &d), PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_FAILS(proxBody_GetDistance(rock, proxBodyId{}, 1.0, &d), PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_FAILS(proxBody_GetDistance(rock, rock, 1.0, &d), PROX_ERROR_INVALID_ARGUMENT, "same body");
  EXPECT_FAILS(proxBody_GetDistance(rock, tool, NAN, &d), PROX_ERROR_INVALID_ARGUMENT, "maxDistance");
  EXPECT_FAILS(proxBody_GetDistance(rock, tool, -1.0, &d), PROX_ERROR_INVALID_ARGUMENT, "maxDistance");
  EXPECT_EQ(d, -1.0);  // set on failure too
  ASSERT_OK(proxBody_GetDistance(rock, tool, 1.0, &d));
  EXPECT_NEAR(d, 0.01, 1e-12);
  ASSERT_OK(proxBody_GetDistance(tool, rock, INFINITY, &d));  // no bound; either order
  EXPECT_NEAR(d, 0.01, 1e-12);
  ASSERT_OK(proxBody_GetDistance(rock, tool, 0.005, &d));  // farther than the bound
  EXPECT_EQ(d, -1.0);
  ASSERT_OK(proxBody_GetDistance(rock, far, INFINITY, &d));  // any body types
  EXPECT_NEAR(d, 2.0, 1e-12);
  const proxPose inside = at(0.5, 0.3, 0.4);
  ASSERT_OK(proxBody_SetPose(tool, &inside));
  ASSERT_OK(proxBody_GetDistance(rock, tool, 0.0, &d));  // crossing: 0
  EXPECT_EQ(d, 0.0);
  // Bodies of two worlds.
  proxWorldDef wd = proxDefaultWorldDef();
  proxWorldId other{};
  ASSERT_OK(proxCreateWorld(&wd, &other));
  const proxMeshDef md = cube.def();
  proxMeshId m{};
  ASSERT_OK(proxWorld_CreateMesh(other, &md, &m));
  proxBodyDef bd = proxDefaultBodyDef();
  bd.mesh = m;
  proxBodyId foreign{};
  ASSERT_OK(proxWorld_CreateBody(other, &bd, &foreign));
  EXPECT_FAILS(proxBody_GetDistance(rock, foreign, 1.0, &d), PROX_ERROR_INVALID_HANDLE, "different worlds");
  EXPECT_OK(proxWorld_Destroy(other));
  EXPECT_FAILS(proxBody_GetDistance(rock, foreign, 1.0, &d), PROX_ERROR_INVALID_HANDLE, "live world");
  ASSERT_OK(proxBody_Destroy(far));
  EXPECT_FAILS(proxBody_GetDistance(rock, far, 1.0, &d), PROX_ERROR_INVALID_HANDLE, "live body");
}

TEST_F(CApi, InspectionFromAnotherThreadIsRefused) {
  const proxBodyId rock = body(PROX_BODY_STATIC, at(0));
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0, 0, 1.01));
  std::vector<proxResult> results;
  std::thread([&] {
    proxMeshStats ms;
    proxSearchStats ss;
    proxTrackStats ts;
    proxIntersectionStats is;
    double d = 0.0;
    results.push_back(proxMesh_GetStats(mesh, &ms));
    results.push_back(proxWorld_GetSearchStats(world, &ss));
    results.push_back(proxWorld_Track(world));
    results.push_back(proxWorld_GetTrackStats(world, &ts));
    results.push_back(proxBody_GetIntersectionStats(tool, &is));
    results.push_back(proxBody_GetDistance(rock, tool, 1.0, &d));
  }).join();
  ASSERT_EQ(results.size(), 6u);
  for (std::size_t i = 0; i < results.size(); ++i)
    EXPECT_EQ(results[i], PROX_ERROR_WRONG_THREAD) << "call " << i;
}

TEST_F(CApi, LoadMeshNamesTheFileOfAnInvalidMesh) {
  // Parses, but every triangle repeats a vertex: no mesh.
  const std::string path = ::testing::TempDir() + "proxima_degenerate.obj";
  FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_TRUE(f);
  std::fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\n", f);
  std::fclose(f);
  proxMeshId m{};
  EXPECT_FAILS(proxWorld_LoadMesh(world, path.c_str(), &m), PROX_ERROR_INVALID_MESH,
               "proxima_degenerate.obj: ");
}

}  // namespace
