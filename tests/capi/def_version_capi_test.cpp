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

// `def` at `version`, made by make(&def, &id) and let go of by destroy(id)
// when made: what the maker said.
template <class Id, class Def, class Make, class Destroy>
proxResult made_at(Def def, int32_t version, Make make, Destroy destroy) {
  def.apiVersion = version;
  Id id{};
  const proxResult r = make(&def, &id);
  if (r == PROX_SUCCESS) destroy(id);
  return r;
}

}  // namespace

class DefVersions : public CApi {
 protected:
  std::vector<DefKind> kinds() {
    proxScriptedDeviceDef scripted = proxDefaultScriptedDeviceDef();
    scripted.poses = path_;
    scripted.poseCount = 2;
    proxBodyDef body = proxDefaultBodyDef();
    body.mesh = mesh;
    body.pose = at(3);
    proxDeviceDef device = proxDefaultDeviceDef();
    device.readPose = [](void*, proxPose* p) -> proxBool {
      *p = at(0);
      return 1;
    };
    const proxWorldId w = world;
    const proxBodyId t = tool;
    return {
        {"proxDefaultWorldDef",
         [](int32_t v) { return made_at<proxWorldId>(proxDefaultWorldDef(), v, proxCreateWorld, proxWorld_Destroy); }},
        {"proxDefaultMeshDef",
         [w, def = cube.def()](int32_t v) {
           return made_at<proxMeshId>(
               def, v, [w](const proxMeshDef* d, proxMeshId* m) { return proxWorld_CreateMesh(w, d, m); },
               proxMesh_Destroy);
         }},
        {"proxDefaultBodyDef",
         [w, body](int32_t v) {
           return made_at<proxBodyId>(
               body, v, [w](const proxBodyDef* d, proxBodyId* b) { return proxWorld_CreateBody(w, d, b); },
               proxBody_Destroy);
         }},
        {"proxDefaultDeviceDef",
         [t, device](int32_t v) {
           proxDeviceDef d = device;
           d.apiVersion = v;
           return proxBody_SetDevice(t, &d);
         }},
        {"proxDefaultScriptedDeviceDef",
         [w, scripted](int32_t v) {
           return made_at<proxScriptedDeviceId>(
               scripted, v,
               [w](const proxScriptedDeviceDef* d, proxScriptedDeviceId* s) {
                 return proxWorld_CreateScriptedDevice(w, d, s);
               },
               proxScriptedDevice_Destroy);
         }},
        {"proxDefaultStreamDeviceDef",
         [w](int32_t v) {
           return made_at<proxStreamDeviceId>(
               proxDefaultStreamDeviceDef(), v,
               [w](const proxStreamDeviceDef* d, proxStreamDeviceId* s) {
                 return proxWorld_CreateStreamDevice(w, d, s);
               },
               proxStreamDevice_Destroy);
         }},
        {"proxDefaultThreadsDef",
         [w](int32_t v) {
           proxThreadsDef d = proxDefaultThreadsDef();
           d.hapticCore = d.localCore = d.globalCore = -1;
           d.apiVersion = v;
           const proxResult r = proxWorld_StartThreads(w, &d);
           if (r == PROX_SUCCESS) proxWorld_StopThreads(w);
           return r;
         }},
    };
  }
  void SetUp() override {
    CApi::SetUp();
    tool = body(PROX_BODY_TOOL, at(2));
  }
  proxBodyId tool{};
  const proxPose path_[2] = {at(0), at(1)};
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
