// The public structs' sizes are part of the ABI; the bindings and the C11
// header test check the same numbers.
#include <proxima/proxima.h>

#include <stddef.h>

static_assert(sizeof(proxWorldId) == 8, "ABI");
static_assert(sizeof(proxMeshId) == 16, "ABI");
static_assert(sizeof(proxBodyId) == 16, "ABI");
static_assert(sizeof(proxVec3) == 24, "ABI");
static_assert(sizeof(proxQuat) == 32, "ABI");
static_assert(sizeof(proxPose) == 56, "ABI");
static_assert(sizeof(proxForceSettings) == 40, "ABI");
static_assert(sizeof(proxWorldDef) == 64, "ABI");
static_assert(offsetof(proxWorldDef, workerCount) == 60, "ABI");
static_assert(sizeof(proxMeshDef) == 40, "ABI");
static_assert(sizeof(proxBodyDef) == 152, "ABI");
static_assert(sizeof(proxContact) == 112, "ABI");
static_assert(sizeof(proxWrench) == 56, "ABI");
static_assert(sizeof(proxWorldStats) == 32, "ABI");
static_assert(sizeof(proxPolylineInfo) == 32, "ABI");
static_assert(sizeof(proxMeshInfo) == 68 + 4, "ABI");
static_assert(sizeof(proxRigInfo) == 16, "ABI");
static_assert(sizeof(proxSkinInfo) == 72, "ABI");
static_assert(sizeof(proxAnimationInfo) == 88, "ABI");
static_assert(sizeof(proxDeviceDef) == 56, "ABI");
static_assert(sizeof(proxScriptedDeviceId) == 16, "ABI");
static_assert(sizeof(proxScriptedDeviceDef) == 40, "ABI");
static_assert(sizeof(proxScriptedDeviceRecord) == 104, "ABI");
static_assert(sizeof(proxThreadsDef) == 120, "ABI");
static_assert(offsetof(proxThreadsDef, globalWorkerCount) == 112, "ABI");
static_assert(sizeof(proxHapticSample) == 192, "ABI");
static_assert(sizeof(proxThreadStats) == 120, "ABI");
static_assert(sizeof(proxSafetyStats) == 48, "ABI");
static_assert(sizeof(proxResult) == 4 && sizeof(proxMethod) == 4 && sizeof(proxBodyType) == 4 &&
                  sizeof(proxThread) == 4,
              "ABI");
static_assert(sizeof(proxForcePreset) == 4, "ABI");
static_assert(sizeof(proxMeshStats) == 48, "ABI");
static_assert(sizeof(proxSearchStats) == 88, "ABI");
static_assert(sizeof(proxTrackStats) == 48, "ABI");
static_assert(sizeof(proxIntersectionStats) == 40, "ABI");
static_assert(sizeof(proxPatchSettings) == 24, "ABI");
static_assert(sizeof(proxPatchStats) == 32, "ABI");
static_assert(sizeof(proxStreamDeviceId) == 16, "ABI");
static_assert(sizeof(proxStreamDeviceDef) == 56, "ABI");
static_assert(sizeof(proxStreamDeviceStats) == 80, "ABI");
static_assert(sizeof(proxStreamMode) == 4, "ABI");
static_assert(sizeof(proxHapticTiming) == 4, "ABI");
static_assert(sizeof(proxToolMode) == 4, "ABI");
static_assert(sizeof(proxContactPatch) == 32, "ABI");
static_assert(sizeof(proxForceCurve) == 4 && sizeof(proxHapticFlag) == 4 && sizeof(proxSleepTimer) == 4, "ABI");
static_assert(sizeof(proxVersion) == 12, "ABI");

// The optional headers' structs, where the library has them.
#if PROX_WITH_HIDAPI
#include <proxima/proxima_hid.h>
static_assert(sizeof(proxHidDeviceInfo) == 464 && sizeof(proxHidDeviceId) == 16, "ABI");
static_assert(sizeof(proxHidDeviceDef) == 240 && sizeof(proxHidDeviceStats) == 120, "ABI");
static_assert(sizeof(proxHidProfile) == 4 && sizeof(proxHidForceEffect) == 4, "ABI");
#endif
#if PROX_WITH_OPENXR
#include <proxima/proxima_openxr.h>
static_assert(sizeof(proxXrDeviceId) == 8 && sizeof(proxXrDeviceDef) == 248 && sizeof(proxXrDeviceStats) == 88,
              "ABI");
static_assert(sizeof(proxXrPoseMode) == 4 && sizeof(proxXrTimeSource) == 4, "ABI");
#endif
