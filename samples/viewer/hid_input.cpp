#include "hid_input.h"

#if PROX_VIEWER_WITH_HID
#include <proxima/proxima_hid.h>
#endif

#include <cstdio>
#include <stdexcept>

namespace viewer {

#if PROX_VIEWER_WITH_HID
namespace {
void check(proxResult r) {
  if (r != PROX_SUCCESS) throw std::runtime_error(std::string("--device hid: ") + proxGetLastError());
}
}  // namespace

bool hid_supported() { return true; }

bool hid_present() {
  int32_t count = 0;
  const proxResult r = proxEnumerateHidDevices(nullptr, 0, &count);
  return (r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY) && count > 0;
}

uint64_t attach_hid(proxWorldId world, proxBodyId tool, const proxPose& start, const proxVec3& reference) {
  proxHidDeviceDef def = proxDefaultHidDeviceDef();
  def.initialPose = start;
  def.referencePoint = reference;
  proxHidDeviceId id;
  check(proxWorld_CreateHidDevice(world, &def, &id));
  proxDeviceDef device;
  check(proxHidDevice_GetDeviceDef(id, &device));
  check(proxBody_SetDevice(tool, &device));
  return (uint64_t(id.reserved) << 32) | id.index1;
}

std::string hid_summary(proxWorldId world, uint64_t device) {
  if (device == 0) return "";
  const proxHidDeviceId id{uint32_t(device), uint32_t(device >> 32), world};
  proxHidDeviceStats s;
  proxPose p;
  if (proxHidDevice_GetStats(id, &s) != PROX_SUCCESS || proxHidDevice_GetPose(id, &p) != PROX_SUCCESS)
    return "";
  char line[320];
  std::snprintf(
      line, sizeof line,
      "hid device: %llu reports read, %llu malformed, %llu outputs written, tool at %.6f %.6f %.6f, "
      "turned %.6f %.6f %.6f %.6f",
      static_cast<unsigned long long>(s.reportsRead), static_cast<unsigned long long>(s.malformed),
      static_cast<unsigned long long>(s.outputsWritten), p.position.x, p.position.y, p.position.z,
      p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  return line;
}
#else
bool hid_supported() { return false; }
bool hid_present() { return false; }
uint64_t attach_hid(proxWorldId, proxBodyId, const proxPose&, const proxVec3&) {
  throw std::runtime_error("--device hid: this libproxima was built without HID devices (PROX_WITH_HIDAPI)");
}
std::string hid_summary(proxWorldId, uint64_t) { return ""; }
#endif

}  // namespace viewer
