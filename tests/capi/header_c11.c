/* The public header compiles as strict C11, and the struct sizes a C
 * compiler sees are the ones the library was built with (and the bindings
 * check). Also: header and library versions agree. */
#include <proxima/proxima.h>

#include <stdio.h>

_Static_assert(sizeof(proxWorldId) == 8, "proxWorldId");
_Static_assert(sizeof(proxMeshId) == 16, "proxMeshId");
_Static_assert(sizeof(proxBodyId) == 16, "proxBodyId");
_Static_assert(sizeof(proxPose) == 56, "proxPose");
_Static_assert(sizeof(proxWorldDef) == 64, "proxWorldDef");
_Static_assert(sizeof(proxMeshDef) == 40, "proxMeshDef");
_Static_assert(sizeof(proxBodyDef) == 152, "proxBodyDef");
_Static_assert(sizeof(proxContact) == 112, "proxContact");
_Static_assert(sizeof(proxWrench) == 56, "proxWrench");
_Static_assert(sizeof(proxWorldStats) == 32, "proxWorldStats");
_Static_assert(sizeof(proxMeshInfo) == 72, "proxMeshInfo");
_Static_assert(sizeof(proxRigInfo) == 16, "proxRigInfo");
_Static_assert(sizeof(proxSkinInfo) == 72, "proxSkinInfo");
_Static_assert(sizeof(proxAnimationInfo) == 88, "proxAnimationInfo");
_Static_assert(sizeof(proxPolylineInfo) == 32, "proxPolylineInfo");
_Static_assert(sizeof(proxDeviceDef) == 56, "proxDeviceDef");
_Static_assert(sizeof(proxScriptedDeviceId) == 16, "proxScriptedDeviceId");
_Static_assert(sizeof(proxScriptedDeviceDef) == 40, "proxScriptedDeviceDef");
_Static_assert(sizeof(proxScriptedDeviceRecord) == 104, "proxScriptedDeviceRecord");
_Static_assert(sizeof(proxThreadsDef) == 120, "proxThreadsDef");
_Static_assert(sizeof(proxThreadStats) == 120, "proxThreadStats");
_Static_assert(sizeof(proxSafetyStats) == 48, "proxSafetyStats");
_Static_assert(sizeof(proxThread) == 4, "enums are 32-bit");
_Static_assert(sizeof(proxResult) == 4, "enums are 32-bit");
_Static_assert(sizeof(proxBodyType) == 4, "enums are 32-bit");
_Static_assert(sizeof(proxForcePreset) == 4, "enums are 32-bit");
_Static_assert(sizeof(proxMeshStats) == 48, "proxMeshStats");
_Static_assert(sizeof(proxSearchStats) == 88, "proxSearchStats");
_Static_assert(sizeof(proxTrackStats) == 48, "proxTrackStats");
_Static_assert(sizeof(proxIntersectionStats) == 40, "proxIntersectionStats");
_Static_assert(sizeof(proxPatchSettings) == 24, "proxPatchSettings");
_Static_assert(sizeof(proxPatchStats) == 32, "proxPatchStats");
_Static_assert(sizeof(proxStreamDeviceId) == 16, "proxStreamDeviceId");
_Static_assert(sizeof(proxStreamDeviceDef) == 56, "proxStreamDeviceDef");
_Static_assert(sizeof(proxStreamDeviceStats) == 80, "proxStreamDeviceStats");
_Static_assert(sizeof(proxStreamMode) == 4, "enums are 32-bit");
_Static_assert(sizeof(proxHapticTiming) == 4, "enums are 32-bit");
_Static_assert(sizeof(proxToolMode) == 4, "enums are 32-bit");

int main(void) {
  const proxVersion v = proxGetVersion();
  if (v.major != PROX_VERSION_MAJOR || v.minor != PROX_VERSION_MINOR || v.patch != PROX_VERSION_PATCH) {
    fprintf(stderr, "header %d.%d.%d, library %d.%d.%d\n", PROX_VERSION_MAJOR, PROX_VERSION_MINOR,
            PROX_VERSION_PATCH, v.major, v.minor, v.patch);
    return 1;
  }
  proxWorldDef def = proxDefaultWorldDef();
  if (def.apiVersion != PROX_API_VERSION) return 1;
  /* proxGetForcePreset in its three C forms: (kind, cutoff) by value,
   * (kind, cutoff, &force), and 0.3's (kind, &force, &cutoff). */
  proxForceSettings own, out;
  double cutoff = 0;
  if (proxGetForcePreset(PROX_FORCE_PRESET_SOFT, &own, &cutoff) != PROX_SUCCESS || !(cutoff > 0)) return 1;
  const proxForceSettings twice = proxGetForcePreset(PROX_FORCE_PRESET_SOFT, 2 * cutoff);
  if (twice.safetyDistance != 2 * own.safetyDistance || twice.maxForce != own.maxForce) return 1;
  if (proxGetForcePreset(PROX_FORCE_PRESET_SOFT, 2 * cutoff, &out) != PROX_SUCCESS) return 1;
  if (out.decayLength != twice.decayLength) return 1;
  if (proxGetForcePreset(PROX_FORCE_PRESET_SOFT, -1.0).maxForce != 0) return 1;
  printf("proxima %d.%d.%d\n", v.major, v.minor, v.patch);
  return 0;
}
