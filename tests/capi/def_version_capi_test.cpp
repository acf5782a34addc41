// Every def carries the API version it was made for (apiVersion, set by its
// proxDefault*Def()), and every call that takes a def checks it the same way:
// same major version, minor not newer than the library's and not older than
// the oldest laid out as this one's (0.4). The HID and OpenXR defs are
// checked in their own suites (tests/hid, tests/openxr).
#include "capi_fixture.h"

#include <functional>
#include <string>

using capi_fixture::at;
using capi_fixture::CApi;

namespace {

// One kind of def: how to try it (with its apiVersion set to `version`) and
// the maker its errors must name.
struct DefKind {
  const char* maker;
  std::function<proxResult(int32_t version)> attempt;
};

}  // namespace

class DefVersions : public CApi {
 protected:
  std::vector<DefKind> kinds() {
    std::vector<DefKind> k;
    k.push_back({"proxDefaultWorldDef", [](int32_t v) {
                   proxWorldDef d = proxDefaultWorldDef();
                   d.apiVersion = v;
                   proxWorldId w{};
                   const proxResult r = proxCreateWorld(&d, &w);
                   if (r == PROX_SUCCESS) proxWorld_Destroy(w);
                   return r;
                 }});
    k.push_back({"proxDefaultMeshDef", [this](int32_t v) {
                   proxMeshDef d = cube.def();
                   d.apiVersion = v;
                   proxMeshId m{};
                   const proxResult r = proxWorld_CreateMesh(world, &d, &m);
                   if (r == PROX_SUCCESS) proxMesh_Destroy(m);
                   return r;
                 }});
    k.push_back({"proxDefaultBodyDef", [this](int32_t v) {
                   proxBodyDef d = proxDefaultBodyDef();
                   d.apiVersion = v;
                   d.mesh = mesh;
                   d.pose = at(3);
                   proxBodyId b{};
                   const proxResult r = proxWorld_CreateBody(world, &d, &b);
                   if (r == PROX_SUCCESS) proxBody_Destroy(b);
                   return r;
                 }});
    k.push_back({"proxDefaultDeviceDef", [this](int32_t v) {
                   proxDeviceDef d = proxDefaultDeviceDef();
                   d.apiVersion = v;
                   d.readPose = [](void*, proxPose* p) -> proxBool {
                     *p = at(0);
                     return 1;
                   };
                   return proxBody_SetDevice(tool, &d);
                 }});
    k.push_back({"proxDefaultScriptedDeviceDef", [this](int32_t v) {
                   const proxPose path[] = {at(0), at(1)};
                   proxScriptedDeviceDef d = proxDefaultScriptedDeviceDef();
                   d.apiVersion = v;
                   d.poses = path;
                   d.poseCount = 2;
                   proxScriptedDeviceId s{};
                   const proxResult r = proxWorld_CreateScriptedDevice(world, &d, &s);
                   if (r == PROX_SUCCESS) proxScriptedDevice_Destroy(s);
                   return r;
                 }});
    k.push_back({"proxDefaultStreamDeviceDef", [this](int32_t v) {
                   proxStreamDeviceDef d = proxDefaultStreamDeviceDef();
                   d.apiVersion = v;
                   proxStreamDeviceId s{};
                   const proxResult r = proxWorld_CreateStreamDevice(world, &d, &s);
                   if (r == PROX_SUCCESS) proxStreamDevice_Destroy(s);
                   return r;
                 }});
    k.push_back({"proxDefaultThreadsDef", [this](int32_t v) {
                   proxThreadsDef d = proxDefaultThreadsDef();
                   d.apiVersion = v;
                   d.hapticCore = d.localCore = d.globalCore = -1;
                   const proxResult r = proxWorld_StartThreads(world, &d);
                   if (r == PROX_SUCCESS) proxWorld_StopThreads(world);
                   return r;
                 }});
    return k;
  }
  void SetUp() override {
    CApi::SetUp();
    tool = body(PROX_BODY_TOOL, at(2));
  }
  proxBodyId tool{};
};

TEST_F(DefVersions, EveryDefTakesItsOwnAndOlderMinorsOfItsMajorAndNothingElse) {
  for (const DefKind& kind : kinds()) {
    SCOPED_TRACE(kind.maker);
    // As its maker made it, and every older minor back to 0.4.
    for (int32_t minor = 4; minor <= PROX_VERSION_MINOR; ++minor)
      EXPECT_EQ(kind.attempt((PROX_VERSION_MAJOR << 16) | minor), PROX_SUCCESS)
          << "version " << PROX_VERSION_MAJOR << "." << minor << ": " << proxGetLastError();
    // A newer minor (a program built against a later header), another
    // major, the 0.3 layout, none at all: refused, naming the def's maker
    // and telling what to do.
    const int32_t refused[] = {PROX_API_VERSION + 1, (PROX_VERSION_MAJOR + 1) << 16, (PROX_VERSION_MAJOR << 16) | 3, 0,
                               -1};
    for (const int32_t version : refused) {
      EXPECT_EQ(kind.attempt(version), PROX_ERROR_VERSION_MISMATCH) << "apiVersion " << version;
      const std::string error = proxGetLastError();
      EXPECT_NE(error.find(kind.maker), std::string::npos) << error;
      EXPECT_NE(error.find("rebuild"), std::string::npos) << error;
    }
  }
}

TEST_F(DefVersions, EveryMakerStampsTheHeadersVersion) {
  EXPECT_EQ(proxDefaultWorldDef().apiVersion, PROX_API_VERSION);
  EXPECT_EQ(proxDefaultMeshDef().apiVersion, PROX_API_VERSION);
  EXPECT_EQ(proxDefaultBodyDef().apiVersion, PROX_API_VERSION);
  EXPECT_EQ(proxDefaultDeviceDef().apiVersion, PROX_API_VERSION);
  EXPECT_EQ(proxDefaultScriptedDeviceDef().apiVersion, PROX_API_VERSION);
  EXPECT_EQ(proxDefaultStreamDeviceDef().apiVersion, PROX_API_VERSION);
  EXPECT_EQ(proxDefaultThreadsDef().apiVersion, PROX_API_VERSION);
  // The device defs the built-in devices hand out are stamped too: they go
  // back in through proxBody_SetDevice.
  proxStreamDeviceDef sd = proxDefaultStreamDeviceDef();
  proxStreamDeviceId stream{};
  ASSERT_OK(proxWorld_CreateStreamDevice(world, &sd, &stream));
  proxDeviceDef dd{};
  ASSERT_OK(proxStreamDevice_GetDeviceDef(stream, &dd));
  EXPECT_EQ(dd.apiVersion, PROX_API_VERSION);
  EXPECT_OK(proxBody_SetDevice(tool, &dd));
}
