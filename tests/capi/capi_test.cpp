// The C API: every function with good and bad input. A fixture turns any
// unexpected library error into a failed test with the library's message.
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


TEST(CApiBasics, VersionResultStringsAndLastError) {
  const proxVersion v = proxGetVersion();
  EXPECT_EQ(v.major, PROX_VERSION_MAJOR);
  EXPECT_EQ(v.minor, PROX_VERSION_MINOR);
  EXPECT_EQ(v.patch, PROX_VERSION_PATCH);
  const proxResult all[] = {PROX_SUCCESS,
                            PROX_ERROR_INVALID_ARGUMENT,
                            PROX_ERROR_INVALID_HANDLE,
                            PROX_ERROR_INVALID_MESH,
                            PROX_ERROR_FILE,
                            PROX_ERROR_PARSE,
                            PROX_ERROR_UNSUPPORTED,
                            PROX_ERROR_VERSION_MISMATCH,
                            PROX_ERROR_WRONG_THREAD,
                            PROX_ERROR_CAPACITY,
                            PROX_ERROR_INTERNAL};
  std::vector<std::string> names;
  for (proxResult r : all) names.push_back(proxResultString(r));
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = i + 1; j < names.size(); ++j) EXPECT_NE(names[i], names[j]);
  EXPECT_STREQ(proxResultString(static_cast<proxResult>(12345)), "unknown proxResult");
  // The last error belongs to the thread that failed.
  EXPECT_FAILS(proxCreateWorld(nullptr, nullptr), PROX_ERROR_INVALID_ARGUMENT, "def is NULL");
  std::string other;
  std::thread([&] { other = proxGetLastError(); }).join();
  EXPECT_EQ(other, "");
  EXPECT_NE(std::string(proxGetLastError()), "");
}

TEST(CApiBasics, CreateWorldValidatesTheDef) {
  proxWorldId w{};
  proxWorldDef def = proxDefaultWorldDef();
  EXPECT_FAILS(proxCreateWorld(&def, nullptr), PROX_ERROR_INVALID_ARGUMENT, "world is NULL");
  proxWorldDef zero{};
  EXPECT_FAILS(proxCreateWorld(&zero, &w), PROX_ERROR_INVALID_ARGUMENT, "proxDefaultWorldDef");
  // Same major version, minor not newer than the library's.
  def.apiVersion = PROX_API_VERSION + 1;
  EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_VERSION_MISMATCH, "API version");
  def.apiVersion = (PROX_VERSION_MAJOR + 1) << 16;
  EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_VERSION_MISMATCH, "takes defs of");
  def.apiVersion = -1;
  EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_VERSION_MISMATCH, "API version");
  // 0.4 grew proxDeviceDef: a 0.3 program is refused, told to rebuild.
  def.apiVersion = (PROX_VERSION_MAJOR << 16) | 3;
  EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_VERSION_MISMATCH, "rebuild");
  for (int32_t minor = 4; minor <= PROX_VERSION_MINOR; ++minor) {
    def.apiVersion = (PROX_VERSION_MAJOR << 16) | minor;
    ASSERT_EQ(proxCreateWorld(&def, &w), PROX_SUCCESS) << "a def of version 0." << minor << ": " << proxGetLastError();
    ASSERT_OK(proxWorld_Destroy(w));
  }
  def = proxDefaultWorldDef();
  struct Bad {
    void (*spoil)(proxWorldDef&);
    const char* field;
  };
  const Bad bad[] = {
      {[](proxWorldDef& d) { d.method = static_cast<proxMethod>(7); }, "method"},
      {[](proxWorldDef& d) { d.method = static_cast<proxMethod>(3); }, "method"},
      {[](proxWorldDef& d) { d.cutoff = NAN; }, "cutoff"},
      {[](proxWorldDef& d) { d.cutoff = -1; }, "cutoff"},
      {[](proxWorldDef& d) { d.cutoff = 0; }, "cutoff"},
      {[](proxWorldDef& d) { d.force.maxForce = 0; }, "maxForce"},
      {[](proxWorldDef& d) { d.force.maxTorque = INFINITY; }, "maxTorque"},
      {[](proxWorldDef& d) { d.force.decayLength = -1; }, "decayLength"},
      {[](proxWorldDef& d) { d.force.safetyDistance = d.cutoff; }, "safetyDistance"},
      {[](proxWorldDef& d) { d.force.curve = static_cast<proxForceCurve>(9); }, "curve"},
  };
  for (const Bad& b : bad) {
    def = proxDefaultWorldDef();
    b.spoil(def);
    EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_INVALID_ARGUMENT, b.field);
    EXPECT_FALSE(proxWorld_IsValid(w));
  }
}

TEST(CApiBasics, StaleAndNullWorldIds) {
  proxWorldDef def = proxDefaultWorldDef();
  proxWorldId w{};
  ASSERT_OK(proxCreateWorld(&def, &w));
  EXPECT_TRUE(proxWorld_IsValid(w));
  ASSERT_OK(proxWorld_Destroy(w));
  EXPECT_FALSE(proxWorld_IsValid(w));
  EXPECT_FAILS(proxWorld_Destroy(w), PROX_ERROR_INVALID_HANDLE, "live world");
  EXPECT_FAILS(proxWorld_Step(w), PROX_ERROR_INVALID_HANDLE, "live world");
  EXPECT_FAILS(proxWorld_Step(proxWorldId{}), PROX_ERROR_INVALID_HANDLE, "null");
  proxWorldStats stats;
  EXPECT_FAILS(proxWorld_GetStats(w, &stats), PROX_ERROR_INVALID_HANDLE, "live world");
  // A new world in the same slot does not revive the old id.
  proxWorldId again{};
  ASSERT_OK(proxCreateWorld(&def, &again));
  EXPECT_FALSE(proxWorld_IsValid(w));
  EXPECT_OK(proxWorld_Destroy(again));
}

// The deprecated name still destroys a world, and names itself when refused.
TEST(CApiBasics, DestroyWorldIsProxWorldDestroysDeprecatedName) {
  proxWorldDef def = proxDefaultWorldDef();
  proxWorldId w{};
  ASSERT_OK(proxCreateWorld(&def, &w));
  ASSERT_OK(proxDestroyWorld(w));
  EXPECT_FALSE(proxWorld_IsValid(w));
  EXPECT_FAILS(proxDestroyWorld(w), PROX_ERROR_INVALID_HANDLE, "proxDestroyWorld");
}

TEST_F(CApi, CallsFromAnotherThreadAreRefused) {
  proxResult step = PROX_SUCCESS, destroy = PROX_SUCCESS;
  std::string message;
  std::thread([&] {
    step = proxWorld_Step(world);
    message = proxGetLastError();
    destroy = proxWorld_Destroy(world);
  }).join();
  EXPECT_EQ(step, PROX_ERROR_WRONG_THREAD);
  EXPECT_EQ(destroy, PROX_ERROR_WRONG_THREAD);
  EXPECT_NE(message.find("game thread"), std::string::npos);
  EXPECT_TRUE(proxWorld_IsValid(world));
}

TEST_F(CApi, MeshAndBodyIdsSayWhetherTheyAreValid) {
  const proxBodyId b = body(PROX_BODY_STATIC, at(0));
  EXPECT_TRUE(proxMesh_IsValid(mesh));
  EXPECT_TRUE(proxBody_IsValid(b));
  EXPECT_STREQ(proxGetLastError(), "");
  // From another thread: false, and the last error there says why.
  proxBool mesh_elsewhere = 1, body_elsewhere = 1;
  std::string why;
  std::thread([&] {
    mesh_elsewhere = proxMesh_IsValid(mesh);
    body_elsewhere = proxBody_IsValid(b);
    why = proxGetLastError();
  }).join();
  EXPECT_FALSE(mesh_elsewhere);
  EXPECT_FALSE(body_elsewhere);
  EXPECT_NE(why.find("game thread"), std::string::npos) << why;
  // Null, destroyed, and an id of another kind's slot in a new generation.
  EXPECT_FALSE(proxMesh_IsValid(proxMeshId{}));
  EXPECT_FALSE(proxBody_IsValid(proxBodyId{}));
  EXPECT_NE(std::string(proxGetLastError()).find("null"), std::string::npos);
  ASSERT_OK(proxBody_Destroy(b));
  EXPECT_FALSE(proxBody_IsValid(b));
  EXPECT_NE(std::string(proxGetLastError()).find("live body"), std::string::npos);
  const proxBodyId again = body(PROX_BODY_STATIC, at(0));  // the same slot, a new generation
  EXPECT_TRUE(proxBody_IsValid(again));
  EXPECT_FALSE(proxBody_IsValid(b));
  ASSERT_OK(proxBody_Destroy(again));
  ASSERT_OK(proxMesh_Destroy(mesh));
  EXPECT_FALSE(proxMesh_IsValid(mesh));
  // A destroyed world's ids.
  const proxMeshId stale_world_mesh = mesh;
  ASSERT_OK(proxWorld_Destroy(world));
  EXPECT_FALSE(proxMesh_IsValid(stale_world_mesh));
  EXPECT_NE(std::string(proxGetLastError()).find("live world"), std::string::npos);
}

TEST_F(CApi, CreateMeshValidatesItsData) {
  proxMeshId m{};
  Cube c;
  proxMeshDef d = c.def();
  EXPECT_FAILS(proxWorld_CreateMesh(world, nullptr, &m), PROX_ERROR_INVALID_ARGUMENT, "def is NULL");
  EXPECT_FAILS(proxWorld_CreateMesh(world, &d, nullptr), PROX_ERROR_INVALID_ARGUMENT, "mesh is NULL");
  EXPECT_FAILS(proxWorld_CreateMesh(proxWorldId{}, &d, &m), PROX_ERROR_INVALID_HANDLE, "null");
  proxMeshDef raw{};
  EXPECT_FAILS(proxWorld_CreateMesh(world, &raw, &m), PROX_ERROR_INVALID_ARGUMENT, "proxDefaultMeshDef");
  c.positions[7] = NAN;  // vertex 2, y
  d = c.def();
  EXPECT_FAILS(proxWorld_CreateMesh(world, &d, &m), PROX_ERROR_INVALID_MESH, "vertex 2");
  Cube out_of_range;
  out_of_range.indices[10] = 99;  // triangle 3
  d = out_of_range.def();
  EXPECT_FAILS(proxWorld_CreateMesh(world, &d, &m), PROX_ERROR_INVALID_MESH, "triangle 3");
  d = Cube().def();
  d.triangleCount = 0;
  EXPECT_FAILS(proxWorld_CreateMesh(world, &d, &m), PROX_ERROR_INVALID_MESH, "no triangles");
  d = Cube().def();
  d.positions = nullptr;
  EXPECT_FAILS(proxWorld_CreateMesh(world, &d, &m), PROX_ERROR_INVALID_MESH, "positions");
  const double p[] = {0, 0, 0, 1, 0, 0};
  const uint32_t i[] = {0, 1, 1};
  d = proxDefaultMeshDef();
  d.positions = p, d.vertexCount = 2, d.indices = i, d.triangleCount = 1;
  EXPECT_FAILS(proxWorld_CreateMesh(world, &d, &m), PROX_ERROR_INVALID_MESH, "non-degenerate");
  EXPECT_EQ(m.index1, 0u);  // failures leave a null id
}

TEST_F(CApi, LoadMeshReportsFileProblems) {
  proxMeshId m{};
  EXPECT_FAILS(proxWorld_LoadMesh(world, nullptr, &m), PROX_ERROR_INVALID_ARGUMENT, "path is NULL");
  EXPECT_FAILS(proxWorld_LoadMesh(world, "/nonexistent/x.obj", &m), PROX_ERROR_FILE, "x.obj");
  EXPECT_FAILS(proxWorld_LoadMesh(world, "model.stl", &m), PROX_ERROR_UNSUPPORTED, ".stl");
  const std::string bad = ::testing::TempDir() + "proxima_bad.obj";
  FILE* f = std::fopen(bad.c_str(), "w");
  ASSERT_TRUE(f);
  std::fputs("v 0 0 0\nv 1 0 0\nf 1 2 9\n", f);
  std::fclose(f);
  EXPECT_FAILS(proxWorld_LoadMesh(world, bad.c_str(), &m), PROX_ERROR_PARSE, ":3");
  ASSERT_OK(proxWorld_LoadMesh(world, PROX_SHARED_ASSETS_DIR "/bunny.obj", &m));
  proxMeshInfo info;
  ASSERT_OK(proxMesh_GetInfo(m, &info));
  EXPECT_EQ(info.triangleCount, 27864u);
  EXPECT_EQ(info.vertexCount, 13934u);
  EXPECT_EQ(info.boundaryEdges, 0u);
}

TEST_F(CApi, MeshInfoAndLifetime) {
  proxMeshInfo info;
  EXPECT_FAILS(proxMesh_GetInfo(mesh, nullptr), PROX_ERROR_INVALID_ARGUMENT, "info is NULL");
  ASSERT_OK(proxMesh_GetInfo(mesh, &info));
  EXPECT_EQ(info.triangleCount, 12u);
  EXPECT_EQ(info.vertexCount, 8u);
  EXPECT_EQ(info.boundaryEdges, 0u);
  EXPECT_EQ(info.boundsMax.z, 1.0);
  const proxBodyId b = body(PROX_BODY_STATIC, at(0));
  EXPECT_FAILS(proxMesh_Destroy(mesh), PROX_ERROR_INVALID_ARGUMENT, "used by 1 bodies");
  ASSERT_OK(proxBody_Destroy(b));
  ASSERT_OK(proxMesh_Destroy(mesh));
  EXPECT_FAILS(proxMesh_Destroy(mesh), PROX_ERROR_INVALID_HANDLE, "live mesh");
  EXPECT_FAILS(proxMesh_GetInfo(mesh, &info), PROX_ERROR_INVALID_HANDLE, "live mesh");
  EXPECT_FAILS(proxMesh_GetInfo(proxMeshId{}, &info), PROX_ERROR_INVALID_HANDLE, "null");
}

TEST_F(CApi, CreateBodyValidatesTheDef) {
  proxBodyId b{};
  proxBodyDef d = proxDefaultBodyDef();
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, &b), PROX_ERROR_INVALID_HANDLE, "null");  // no mesh set
  d.mesh = mesh;
  EXPECT_FAILS(proxWorld_CreateBody(world, nullptr, &b), PROX_ERROR_INVALID_ARGUMENT, "def is NULL");
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, nullptr), PROX_ERROR_INVALID_ARGUMENT, "body is NULL");
  proxBodyDef raw{};
  raw.mesh = mesh;
  EXPECT_FAILS(proxWorld_CreateBody(world, &raw, &b), PROX_ERROR_INVALID_ARGUMENT, "proxDefaultBodyDef");
  d.type = static_cast<proxBodyType>(5);
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, &b), PROX_ERROR_INVALID_ARGUMENT, "type");
  d.type = PROX_BODY_TOOL;
  d.pose.position.y = NAN;
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, &b), PROX_ERROR_INVALID_ARGUMENT, "def->pose.position.y");
  d.pose = at(0);
  d.pose.rotation = {0, 0, 0, 0};
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, &b), PROX_ERROR_INVALID_ARGUMENT, "zero quaternion");
  d.pose = at(0);
  d.referencePoint.x = INFINITY;
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, &b), PROX_ERROR_INVALID_ARGUMENT, "referencePoint");
  // A mesh of another world.
  proxWorldDef wd = proxDefaultWorldDef();
  proxWorldId other{};
  ASSERT_OK(proxCreateWorld(&wd, &other));
  const proxMeshDef md = cube.def();
  proxMeshId foreign{};
  ASSERT_OK(proxWorld_CreateMesh(other, &md, &foreign));
  d = proxDefaultBodyDef();
  d.mesh = foreign;
  EXPECT_FAILS(proxWorld_CreateBody(world, &d, &b), PROX_ERROR_INVALID_HANDLE, "another world");
  EXPECT_OK(proxWorld_Destroy(other));
  // Ids of bodies of a destroyed world are stale.
  EXPECT_FAILS(proxWorld_CreateBody(other, &d, &b), PROX_ERROR_INVALID_HANDLE, "live world");
}

TEST_F(CApi, PosesRoundTripAndAreValidated) {
  const proxBodyId fixed = body(PROX_BODY_STATIC, at(0));
  const proxBodyId moving = body(PROX_BODY_MOVABLE, at(5));
  proxPose p = {{1, 2, 3}, {2, 0, 0, 0}};  // not unit: normalised
  EXPECT_FAILS(proxBody_SetPose(fixed, &p), PROX_ERROR_INVALID_ARGUMENT, "static");
  EXPECT_FAILS(proxBody_SetPose(moving, nullptr), PROX_ERROR_INVALID_ARGUMENT, "pose is NULL");
  ASSERT_OK(proxBody_SetPose(moving, &p));
  proxPose back;
  ASSERT_OK(proxBody_GetPose(moving, &back));
  EXPECT_DOUBLE_EQ(back.position.z, 3.0);
  EXPECT_NEAR(back.rotation.w, 1.0, 1e-15);
  EXPECT_FAILS(proxBody_GetPose(moving, nullptr), PROX_ERROR_INVALID_ARGUMENT, "pose is NULL");
  p.rotation.x = NAN;
  EXPECT_FAILS(proxBody_SetPose(moving, &p), PROX_ERROR_INVALID_ARGUMENT, "pose.rotation");
  ASSERT_OK(proxBody_Destroy(moving));
  EXPECT_FAILS(proxBody_Destroy(moving), PROX_ERROR_INVALID_HANDLE, "live body");
  EXPECT_FAILS(proxBody_GetPose(moving, &back), PROX_ERROR_INVALID_HANDLE, "live body");
  EXPECT_FAILS(proxBody_SetPose(proxBodyId{}, &p), PROX_ERROR_INVALID_HANDLE, "world");
}

TEST_F(CApi, ContactsWrenchAndStats) {
  const proxBodyId rock = body(PROX_BODY_STATIC, at(0));
  // The tool cube sits 10 mm above the rock cube, face to face.
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0, 0, 1.01));
  ASSERT_OK(proxWorld_Step(world));
  int32_t count = -1;
  EXPECT_FAILS(proxBody_GetContacts(tool, nullptr, 0, nullptr), PROX_ERROR_INVALID_ARGUMENT, "count is NULL");
  EXPECT_FAILS(proxBody_GetContacts(tool, nullptr, -1, &count), PROX_ERROR_INVALID_ARGUMENT, "negative");
  EXPECT_FAILS(proxBody_GetContacts(tool, nullptr, 4, &count), PROX_ERROR_INVALID_ARGUMENT,
               "contacts is NULL");
  EXPECT_FAILS(proxBody_GetContacts(rock, nullptr, 0, &count), PROX_ERROR_INVALID_ARGUMENT, "PROX_BODY_TOOL");
  EXPECT_FAILS(proxBody_GetContacts(tool, nullptr, 0, &count), PROX_ERROR_CAPACITY, "capacity 0");
  ASSERT_GE(count, 1);
  std::vector<proxContact> contacts(static_cast<std::size_t>(count));
  ASSERT_OK(proxBody_GetContacts(tool, contacts.data(), count, &count));
  for (const proxContact& c : contacts) {
    EXPECT_NEAR(c.distance, 0.01, 1e-12);
    EXPECT_NEAR(c.normal.z, 1.0, 1e-12);  // from the rock up to the tool
    EXPECT_EQ(c.other.index1, rock.index1);
    EXPECT_NEAR(c.pointTool.z - c.pointOther.z, 0.01, 1e-12);
  }
  proxWrench w;
  EXPECT_FAILS(proxBody_GetWrench(tool, nullptr), PROX_ERROR_INVALID_ARGUMENT, "wrench is NULL");
  EXPECT_FAILS(proxBody_GetWrench(rock, &w), PROX_ERROR_INVALID_ARGUMENT, "PROX_BODY_TOOL");
  ASSERT_OK(proxBody_GetWrench(tool, &w));
  EXPECT_GT(w.force.z, 0.0);  // pushed up, away from the rock
  EXPECT_NEAR(w.force.x, 0.0, 1e-12);

  proxWorldStats s;
  EXPECT_FAILS(proxWorld_GetStats(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats is NULL");
  ASSERT_OK(proxWorld_GetStats(world, &s));
  EXPECT_EQ(s.bodies, 2);
  EXPECT_EQ(s.tools, 1);
  EXPECT_EQ(s.pairsInRange, 1);
  EXPECT_EQ(s.pairsSearched, 1);
  EXPECT_EQ(s.contacts, count);
  // Nothing moved: the pair is not searched again, and the answer stands.
  ASSERT_OK(proxWorld_Step(world));
  ASSERT_OK(proxWorld_GetStats(world, &s));
  EXPECT_EQ(s.pairsInRange, 1);
  EXPECT_EQ(s.pairsSearched, 0);
  EXPECT_EQ(s.contacts, count);
  // Moved out of range: no pair, no contact, no force.
  const proxPose away = at(0, 0, 2);
  ASSERT_OK(proxBody_SetPose(tool, &away));
  ASSERT_OK(proxWorld_Step(world));
  ASSERT_OK(proxWorld_GetStats(world, &s));
  EXPECT_EQ(s.pairsInRange, 0);
  EXPECT_EQ(s.contacts, 0);
  ASSERT_OK(proxBody_GetWrench(tool, &w));
  EXPECT_EQ(w.force.z, 0.0);
}

TEST_F(CApi, IntersectionPolylines) {
  const proxBodyId rock = body(PROX_BODY_STATIC, at(0));
  // The tool cube pushed into the rock by (0.5, 0.3, 0.4): the surfaces cross
  // in one closed loop of length 0.6 + 0.7 + 0.6 + 0.5 + 0.7 + 0.5 = 3.6.
  const proxBodyId tool = body(PROX_BODY_TOOL, at(0.5, 0.3, 0.4));
  int32_t points = -1, lines = -1;
  EXPECT_FAILS(proxBody_GetIntersections(tool, nullptr, 0, nullptr, nullptr, 0, &lines),
               PROX_ERROR_INVALID_ARGUMENT, "pointCount is NULL");
  EXPECT_FAILS(proxBody_GetIntersections(tool, nullptr, 0, &points, nullptr, 0, nullptr),
               PROX_ERROR_INVALID_ARGUMENT, "lineCount is NULL");
  EXPECT_FAILS(proxBody_GetIntersections(tool, nullptr, -1, &points, nullptr, 0, &lines),
               PROX_ERROR_INVALID_ARGUMENT, "negative");
  EXPECT_FAILS(proxBody_GetIntersections(tool, nullptr, 8, &points, nullptr, 0, &lines),
               PROX_ERROR_INVALID_ARGUMENT, "points is NULL");
  EXPECT_FAILS(proxBody_GetIntersections(rock, nullptr, 0, &points, nullptr, 0, &lines),
               PROX_ERROR_INVALID_ARGUMENT, "PROX_BODY_TOOL");
  EXPECT_FAILS(proxBody_GetIntersections(tool, nullptr, 0, &points, nullptr, 0, &lines), PROX_ERROR_CAPACITY,
               "do not fit");
  ASSERT_EQ(lines, 1);
  ASSERT_GE(points, 6);
  std::vector<proxVec3> p(static_cast<std::size_t>(points));
  proxPolylineInfo info{};
  ASSERT_OK(proxBody_GetIntersections(tool, p.data(), points, &points, &info, 1, &lines));
  EXPECT_EQ(info.other.index1, rock.index1);
  EXPECT_EQ(info.firstPoint, 0);
  EXPECT_EQ(info.pointCount, points);
  EXPECT_TRUE(info.closed);
  double length = 0.0;
  for (int32_t k = 0; k < points; ++k) {
    const proxVec3 &u = p[static_cast<std::size_t>(k)], &v = p[static_cast<std::size_t>((k + 1) % points)];
    length += std::sqrt((u.x - v.x) * (u.x - v.x) + (u.y - v.y) * (u.y - v.y) + (u.z - v.z) * (u.z - v.z));
  }
  EXPECT_NEAR(length, 3.6, 1e-12);
  // Apart: nothing.
  const proxPose away = at(3, 0, 0);
  ASSERT_OK(proxBody_SetPose(tool, &away));
  ASSERT_OK(proxBody_GetIntersections(tool, nullptr, 0, &points, nullptr, 0, &lines));
  EXPECT_EQ(points, 0);
  EXPECT_EQ(lines, 0);
}

TEST_F(CApi, OnlyPairsInRangeCostAnything) {
  // 120 small cubes on a 2 m grid; the tool is near exactly one of them.
  Cube small(0.1);
  const proxMeshDef md = small.def();
  proxMeshId small_mesh{};
  ASSERT_OK(proxWorld_CreateMesh(world, &md, &small_mesh));
  proxBodyDef d = proxDefaultBodyDef();
  d.mesh = small_mesh;
  for (int i = 0; i < 120; ++i) {
    d.pose = at(2.0 * (i % 12), 2.0 * (i / 12));
    proxBodyId b{};
    ASSERT_OK(proxWorld_CreateBody(world, &d, &b));
  }
  d.type = PROX_BODY_TOOL;
  d.pose = at(2.0 * 5 + 0.12, 2.0 * 3);  // 2 cm beside cube (5, 3)
  proxBodyId tool{};
  ASSERT_OK(proxWorld_CreateBody(world, &d, &tool));
  ASSERT_OK(proxWorld_Step(world));
  proxWorldStats s;
  ASSERT_OK(proxWorld_GetStats(world, &s));
  EXPECT_EQ(s.bodies, 121);
  EXPECT_EQ(s.pairsInRange, 1);
  EXPECT_EQ(s.pairsSearched, 1);
  EXPECT_GT(s.contacts, 0);
}

}  // namespace
