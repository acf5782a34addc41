// HID report descriptors as a device may send them, broken or hostile
// (sdk/src/devices/hid_descriptor.h), and the HID PID layout and reports
// made from whatever parses (hid_pid.h, hid_pid_reports.h): an error names
// the byte and leaves nothing behind; every field lies inside its report;
// every report encoded for a PID device is its declared size and id.
#include "check.h"
#include "devices/hid_descriptor.h"
#include "devices/hid_pid.h"
#include "devices/hid_pid_reports.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

using namespace prox::devices;

namespace {

void check_report(const std::vector<std::uint8_t>& r, const PidSlot& s, const char* what) {
  PROX_FUZZ_CHECK(!r.empty(), "%s: an empty report", what);
  if (!s.present) return;
  PROX_FUZZ_CHECK(r.size() == std::max<std::uint32_t>(s.report_bytes, 1u), "%s: %zu bytes, declared %u", what,
                  r.size(), s.report_bytes);
  PROX_FUZZ_CHECK(r[0] == s.report_id, "%s: id %u, declared %u", what, r[0], s.report_id);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  HidDescriptor d;
  const prox::Status s = parse_hid_descriptor(data, size, d);
  if (!s) {
    PROX_FUZZ_CHECK(s.message().rfind("HID report descriptor, byte ", 0) == 0, "error without the byte: %s",
                    s.message().c_str());
    PROX_FUZZ_CHECK(d.fields.empty(), "a refused descriptor left %zu fields", d.fields.size());
    return 0;
  }
  for (const HidField& f : d.fields) {
    const std::uint64_t end = std::uint64_t{f.bit} + std::uint64_t{f.size} * f.count;
    PROX_FUZZ_CHECK(end <= 8u * 4096u, "a field ends at bit %llu", static_cast<unsigned long long>(end));
    PROX_FUZZ_CHECK(d.report_bytes(f.kind, f.report_id) * 8ull >= end, "a field past its report's size");
    if (f.variable()) PROX_FUZZ_CHECK(f.usages.size() == f.count, "a variable field without a usage a slot");
  }
  PidLayout p;
  const prox::Status l = pid_layout_of(d, p);
  if (!l || !p.pid) {
    PROX_FUZZ_CHECK(!p.pid, "a refused layout says pid");
    return 0;
  }
  PROX_FUZZ_CHECK(p.axes == 1 || p.axes == 2, "%d axes", p.axes);
  check_report(pid_device_control(p, PidControl::Reset), p.control, "Device Control");
  check_report(pid_device_gain(p, 0.5), p.device_gain, "Device Gain");
  check_report(pid_create_constant_force(p), p.create_type, "Create New Effect");
  const std::vector<std::uint8_t> request = pid_block_load_request(p);
  check_report(request, p.load_block, "Block Load");
  (void)pid_parse_block_load(p, request.data(), request.size());
  (void)pid_parse_block_load(p, data, size);
  check_report(pid_set_constant_effect(p, 1, 100, static_cast<std::uint32_t>(size % 36000)), p.effect_block, "Set Effect");
  check_report(pid_set_constant_force(p, 1, -0.75), p.magnitude, "Set Constant Force");
  check_report(pid_effect_start(p, 1, 1), p.operation, "Effect Operation");
  check_report(pid_effect_stop(p, 1), p.operation, "Effect Operation");
  check_report(pid_block_free(p, 1), p.free_block, "Block Free");
  return 0;
}
