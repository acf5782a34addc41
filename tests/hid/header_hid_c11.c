/* proxima_hid.h compiles as strict C11, with the struct sizes worked out by
 * hand from its fields (the bindings will rely on them), and links. */
#include <proxima/proxima_hid.h>

#include <stdio.h>

_Static_assert(sizeof(proxHidDeviceInfo) == 464, "2 + 2 + 4 + 4 + 2 + 2 + 128 + 64 + 256");
_Static_assert(sizeof(proxHidDeviceId) == 16, "proxHidDeviceId");
_Static_assert(sizeof(proxHidDeviceDef) == 192, "8 + 4 (+4) + 56 + 24 + 4 * 8 + 32 + 3 * 8 + 8");
_Static_assert(sizeof(proxHidDeviceStats) == 80, "4 + 4 + 8 * 8 + 8");
_Static_assert(sizeof(proxHidProfile) == 4, "proxHidProfile");

int main(void) {
  int32_t count = -1;
  const proxResult r = proxEnumerateHidDevices(NULL, 0, &count);
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) {
    fprintf(stderr, "proxEnumerateHidDevices: %s\n", proxGetLastError());
    return 1;
  }
  const proxHidDeviceDef def = proxDefaultHidDeviceDef();
  if (def.outputRate != 250.0 || def.deviceToWorld.w != 1.0) return 1;
  printf("%d supported HID devices present\n", (int)count);
  return count >= 0 ? 0 : 1;
}
