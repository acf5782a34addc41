/* proxima_hid.h compiles as strict C11, with the struct sizes worked out by
 * hand from its fields (the bindings will rely on them), and links. */
#include <proxima/proxima_hid.h>

#include <stdio.h>

_Static_assert(sizeof(proxHidDeviceInfo) == 464, "2 + 2 + 4 + 4 + 2 + 2 + 128 + 64 + 256");
_Static_assert(sizeof(proxHidDeviceId) == 16, "proxHidDeviceId");
_Static_assert(sizeof(proxHidDeviceDef) == 240, "4 (+4) + 8 + 4 (+4) + 56 + 24 + 4 * 8 + 32 + 3 * 8 + 2 * 8 + 2 * 4 + 2 * 8 + 8");
_Static_assert(sizeof(proxHidDeviceStats) == 120, "4 + 4 + 8 * 8 + 8 + 2 * 8 + 2 * 8 + 4 + 4");
_Static_assert(sizeof(proxHidForceEffect) == 4, "proxHidForceEffect");
_Static_assert(sizeof(proxHidProfile) == 4, "proxHidProfile");

int main(void) {
  int32_t count = -1;
  const proxResult r = proxEnumerateHidDevices(NULL, 0, &count);
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) {
    fprintf(stderr, "proxEnumerateHidDevices: %s\n", proxGetLastError());
    return 1;
  }
  const proxHidDeviceDef def = proxDefaultHidDeviceDef();
  if (def.outputRate != 250.0 || def.deviceToWorld.w != 1.0 || def.maxForce != 5.0 || def.workspace != 0.0)
    return 1;
  printf("%d supported HID devices present\n", (int)count);
  return count >= 0 ? 0 : 1;
}
