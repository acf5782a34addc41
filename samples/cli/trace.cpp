// `run --trace FILE.csv`: the flight recorder's ticks (proxBody_GetHapticTrace)
// as CSV, one row a haptic tick, for plotting what the hand felt
// (bindings/python/examples/haptic_trace.py; docs/haptic-fidelity.md).
#include "cli.h"

#include <cstdio>
#include <string>
#include <vector>

namespace proxcli {

int trace_capacity_for(double seconds, double haptic_rate) {
  // The run, its start and its fade-out, bounded by what the C API accepts.
  const double ticks = (seconds + 1.0) * haptic_rate;
  return ticks >= double(1 << 20) ? (1 << 20) : static_cast<int>(ticks);
}

std::size_t write_trace_csv(proxBodyId tool, int capacity, const std::string& path) {
  std::vector<proxHapticSample> samples(static_cast<std::size_t>(capacity));
  int32_t count = 0;
  check(proxBody_GetHapticTrace(tool, samples.data(), capacity, &count));
  std::string text =
      "tick,time,device_x,device_y,device_z,device_qw,device_qx,device_qy,device_qz,"
      "proxy_x,proxy_y,proxy_z,proxy_qw,proxy_qx,proxy_qy,proxy_qz,"
      "force_x,force_y,force_z,torque_x,torque_y,torque_z,contacts,closest,"
      "clipped,stale,untrusted,faded,no_pose,stopping\n";
  char row[1024];
  auto pose = [](const proxPose& p, char* out, std::size_t n) {
    std::snprintf(out, n, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", p.position.x, p.position.y, p.position.z,
                  p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  };
  for (int32_t i = 0; i < count; ++i) {
    const proxHapticSample& s = samples[std::size_t(i)];
    char device[256], proxy[256];
    pose(s.devicePose, device, sizeof device);
    pose(s.proxyPose, proxy, sizeof proxy);
    auto flag = [&s](uint32_t bit) { return (s.flags & bit) != 0 ? 1 : 0; };
    std::snprintf(row, sizeof row, "%llu,%.9f,%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%d,%d,%d,%d,%d,%d\n",
                  static_cast<unsigned long long>(s.tick), s.time, device, proxy, s.force.x, s.force.y, s.force.z,
                  s.torque.x, s.torque.y, s.torque.z, s.contactCount, s.closestDistance,
                  flag(PROX_HAPTIC_CLIPPED), flag(PROX_HAPTIC_STALE), flag(PROX_HAPTIC_UNTRUSTED),
                  flag(PROX_HAPTIC_FADED), flag(PROX_HAPTIC_NO_POSE), flag(PROX_HAPTIC_STOPPING));
    text += row;
  }
  write_file(path, text);
  return static_cast<std::size_t>(count);
}

}  // namespace proxcli
