// The C API on inputs at the edges: warnings for what a glTF load skipped
// (proxMesh_GetWarnings), 10^7 triangles repeating one vertex, coordinates
// and quaternions near the double range's ends, enum fields holding any
// int32, thread settings whose periods would not fit a clock.
#include "expect.h"

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

class World : public ::testing::Test {
 protected:
  void SetUp() override {
    const proxWorldDef def = proxDefaultWorldDef();
    ASSERT_OK(proxCreateWorld(&def, &world_));
  }
  void TearDown() override { EXPECT_OK(proxWorld_Destroy(world_)); }

  proxMeshId triangle(double scale = 1.0) {
    const double positions[] = {0, 0, 0, scale, 0, 0, 0, scale, 0};
    const uint32_t indices[] = {0, 1, 2};
    proxMeshDef def = proxDefaultMeshDef();
    def.positions = positions;
    def.vertexCount = 3;
    def.indices = indices;
    def.triangleCount = 1;
    proxMeshId mesh{};
    EXPECT_OK(proxWorld_CreateMesh(world_, &def, &mesh));
    return mesh;
  }

  proxWorldId world_{};
};

#if PROX_WITH_GLTF_TESTS
// A one-triangle glTF whose NORMAL accessor (30 VEC3 floats) runs past its
// 36-byte buffer view; with `valid`, the NORMAL accessor fits.
std::string write_gltf(const std::string& name, bool valid) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path)
      << "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":2},\"indices\":1}]}],"
         "\"buffers\":[{\"byteLength\":42,\"uri\":\"data:application/octet-stream;base64,"
         "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA\"}],"
         "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},"
         "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
         "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
         "{\"bufferView\":0,\"componentType\":5126,\"count\":"
      << (valid ? 3 : 30) << ",\"type\":\"VEC3\"}]}";
  return path;
}

TEST_F(World, GetWarningsReportsTheSkippedNormalAccessor) {
  const std::string path = write_gltf("proxima-inputs-bad-normal.gltf", false);
  proxMeshId mesh{};
  ASSERT_OK(proxWorld_LoadMesh(world_, path.c_str(), &mesh));
  proxMeshInfo info;
  ASSERT_OK(proxMesh_GetInfo(mesh, &info));
  EXPECT_EQ(info.triangleCount, 1u);

  // Ask the size, then fetch.
  int32_t length = -1;
  EXPECT_EQ(proxMesh_GetWarnings(mesh, nullptr, 0, &length), PROX_ERROR_CAPACITY);
  ASSERT_GT(length, 0);
  std::vector<char> text(static_cast<std::size_t>(length) + 1, 'x');
  ASSERT_OK(proxMesh_GetWarnings(mesh, text.data(), length + 1, &length));
  const std::string warnings(text.data());
  EXPECT_EQ(warnings.size(), static_cast<std::size_t>(length));
  EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 1) << warnings;
  EXPECT_EQ(warnings.back(), '\n');
  EXPECT_NE(warnings.find(path + ": mesh 0 primitive 0: NORMAL accessor 2"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("run past the end of the bufferView (36 bytes)"), std::string::npos) << warnings;

  // Too small a buffer: what fits, NUL-terminated, and the whole length.
  char small[8];
  EXPECT_FAILS(proxMesh_GetWarnings(mesh, small, 8, &length), PROX_ERROR_CAPACITY, "bytes");
  EXPECT_EQ(std::string(small), warnings.substr(0, 7));
  EXPECT_EQ(length, static_cast<int32_t>(warnings.size()));

  EXPECT_FAILS(proxMesh_GetWarnings(mesh, text.data(), length + 1, nullptr), PROX_ERROR_INVALID_ARGUMENT,
               "length");
  EXPECT_FAILS(proxMesh_GetWarnings(mesh, nullptr, 4, &length), PROX_ERROR_INVALID_ARGUMENT, "buffer");
  EXPECT_FAILS(proxMesh_GetWarnings(mesh, text.data(), -1, &length), PROX_ERROR_INVALID_ARGUMENT, "capacity");

  // Destroyed: the id is stale, and the slot's next mesh has no warnings.
  ASSERT_OK(proxMesh_Destroy(mesh));
  EXPECT_FAILS(proxMesh_GetWarnings(mesh, nullptr, 0, &length), PROX_ERROR_INVALID_HANDLE, "mesh");
  const proxMeshId next = triangle();
  EXPECT_OK(proxMesh_GetWarnings(next, nullptr, 0, &length));
  EXPECT_EQ(length, 0);
  std::remove(path.c_str());
}

TEST_F(World, AValidFileAndAnArrayMeshHaveNoWarnings) {
  const std::string path = write_gltf("proxima-inputs-good-normal.gltf", true);
  proxMeshId mesh{};
  ASSERT_OK(proxWorld_LoadMesh(world_, path.c_str(), &mesh));
  int32_t length = -1;
  char text[4] = "abc";
  EXPECT_OK(proxMesh_GetWarnings(mesh, text, 4, &length));
  EXPECT_EQ(length, 0);
  EXPECT_STREQ(text, "");
  EXPECT_OK(proxMesh_GetWarnings(triangle(), nullptr, 0, &length));
  EXPECT_EQ(length, 0);
  std::remove(path.c_str());
}
#endif

TEST_F(World, TenMillionTrianglesRepeatingOneVertex) {
  constexpr uint32_t kTriangles = 10000000;
  const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<uint32_t> indices(3 * std::size_t{kTriangles}, 0);  // every triangle is vertex 0 three times
  proxMeshDef def = proxDefaultMeshDef();
  def.positions = positions;
  def.vertexCount = 3;
  def.indices = indices.data();
  def.triangleCount = kTriangles;
  proxMeshId mesh{};
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FAILS(proxWorld_CreateMesh(world_, &def, &mesh), PROX_ERROR_INVALID_MESH,
               "no non-degenerate triangles");
  EXPECT_EQ(mesh.index1, 0u);
  // The same with one real triangle at the end: it alone is kept.
  indices[indices.size() - 2] = 1;
  indices[indices.size() - 1] = 2;
  ASSERT_OK(proxWorld_CreateMesh(world_, &def, &mesh));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  proxMeshInfo info;
  ASSERT_OK(proxMesh_GetInfo(mesh, &info));
  EXPECT_EQ(info.triangleCount, 1u);
  EXPECT_EQ(info.droppedTriangles, kTriangles - 1);
  EXPECT_EQ(info.vertexCount, 3u);
  EXPECT_LT(seconds, 60.0);  // linear in the triangles: about a second here
}

TEST_F(World, CoordinatesBeyondTheSupportedRangeAreRefused) {
  double positions[] = {0, 0, 0, 1, 0, 0, 0, 1e51, 0};
  const uint32_t indices[] = {0, 1, 2};
  proxMeshDef def = proxDefaultMeshDef();
  def.positions = positions;
  def.vertexCount = 3;
  def.indices = indices;
  def.triangleCount = 1;
  proxMeshId mesh{};
  EXPECT_FAILS(proxWorld_CreateMesh(world_, &def, &mesh), PROX_ERROR_INVALID_MESH, "coordinate of 1e+51");
  positions[7] = 1.7976931348623157e308;
  EXPECT_FAILS(proxWorld_CreateMesh(world_, &def, &mesh), PROX_ERROR_INVALID_MESH, "+-1e50");
  positions[7] = 1e49;
  EXPECT_OK(proxWorld_CreateMesh(world_, &def, &mesh));

  proxBodyDef body = proxDefaultBodyDef();
  body.mesh = triangle();
  body.pose.position.x = -2e50;
  proxBodyId id{};
  EXPECT_FAILS(proxWorld_CreateBody(world_, &body, &id), PROX_ERROR_INVALID_ARGUMENT,
               "def->pose.position has a coordinate of -2e+50");
  body.pose.position.x = 0;
  ASSERT_OK(proxWorld_CreateBody(world_, &body, &id));
  proxPose far = body.pose;
  far.position.z = 1e300;
  EXPECT_FAILS(proxBody_SetPose(id, &far), PROX_ERROR_INVALID_ARGUMENT, "pose.position");
}

TEST_F(World, QuaternionsOfAnyFiniteSizeAreNormalised) {
  proxBodyDef body = proxDefaultBodyDef();
  body.mesh = triangle();
  body.type = PROX_BODY_MOVABLE;
  proxBodyId id{};
  ASSERT_OK(proxWorld_CreateBody(world_, &body, &id));
  for (const double s : {7e255, 1e300, 1e-11}) {
    SCOPED_TRACE(s);
    proxPose pose = body.pose;
    pose.rotation = {0.0, s, 0.0, 0.0};  // a half turn about x
    ASSERT_OK(proxBody_SetPose(id, &pose));
    proxPose got{};
    ASSERT_OK(proxBody_GetPose(id, &got));
    EXPECT_NEAR(std::abs(got.rotation.x), 1.0, 1e-15);
    EXPECT_NEAR(got.rotation.w, 0.0, 1e-15);
  }
  // A length of at most 1e-12 is taken for a zero quaternion, as before.
  proxPose zero = body.pose;
  for (const double s : {0.0, 1e-13, 1e-300}) {
    zero.rotation = {0.0, s, 0.0, 0.0};
    EXPECT_FAILS(proxBody_SetPose(id, &zero), PROX_ERROR_INVALID_ARGUMENT, "zero quaternion");
  }
}

TEST(CApiEnums, AnyInt32InAnEnumFieldIsRefusedByName) {
  for (const int32_t value : {-1, -2147483647 - 1, 3, 2147483647}) {
    SCOPED_TRACE(value);
    proxWorldDef def = proxDefaultWorldDef();
    std::memcpy(&def.method, &value, sizeof value);  // as a C caller or a binding may store it
    proxWorldId world{};
    EXPECT_FAILS(proxCreateWorld(&def, &world), PROX_ERROR_INVALID_ARGUMENT,
                 "def->method is not a proxMethod");
    def = proxDefaultWorldDef();
    std::memcpy(&def.force.curve, &value, sizeof value);
    EXPECT_FAILS(proxCreateWorld(&def, &world), PROX_ERROR_INVALID_ARGUMENT, "def->force.curve");
  }
}

TEST_F(World, ThreadRatesWhosePeriodsWouldNotFitAreRefused) {
  proxThreadsDef def = proxDefaultThreadsDef();
  def.hapticRate = 5e-324;  // a period of infinity
  EXPECT_FAILS(proxWorld_StartThreads(world_, &def), PROX_ERROR_INVALID_ARGUMENT,
               "haptic rate must be in [1, 100000]");
  def = proxDefaultThreadsDef();
  def.localRate = 0.5;
  EXPECT_FAILS(proxWorld_StartThreads(world_, &def), PROX_ERROR_INVALID_ARGUMENT, "local rate");
  def = proxDefaultThreadsDef();
  def.globalRate = 1e-300;
  EXPECT_FAILS(proxWorld_StartThreads(world_, &def), PROX_ERROR_INVALID_ARGUMENT, "global rate");
  def = proxDefaultThreadsDef();
  def.maxContacts = 2147483647;  // refused, after reserving no more than the limit
  EXPECT_FAILS(proxWorld_StartThreads(world_, &def), PROX_ERROR_INVALID_ARGUMENT, "maximum contacts");
}

}  // namespace
