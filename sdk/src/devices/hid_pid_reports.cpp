#include "devices/hid_pid_reports.h"

#include <algorithm>
#include <cmath>

namespace prox::devices {
namespace {

// A report of slot's id and size, zeroed.
std::vector<std::uint8_t> report_of(const PidSlot& s) {
  std::vector<std::uint8_t> r(std::max<std::uint32_t>(s.report_bytes, 1u), 0u);
  r[0] = s.report_id;
  return r;
}

void put(std::vector<std::uint8_t>& r, const PidSlot& s, std::int64_t value) {
  if (!s.present) return;
  value = std::clamp<std::int64_t>(value, s.min, s.max);
  write_hid_bits(r.data(), r.size(), s.bit, s.bits, value);
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

PidForce pid_force_of(double fx, double fy, double max_force, int axes, PidForceSign sign) {
  PidForce out;
  if (!(max_force > 0.0) || !std::isfinite(fx) || !std::isfinite(fy)) return out;
  const double s = static_cast<double>(static_cast<int>(sign));
  if (axes == 1) {
    // East (9000): a DirectInput magnitude pushes along (-1, 0).
    out.direction_centidegrees = 9000;
    out.magnitude = std::clamp(-s * fx / max_force, -1.0, 1.0);
    return out;
  }
  const double size = std::hypot(fx, fy);
  if (!(size > 0.0)) return out;
  // (-sin theta, cos theta) = the push's direction (for the opposite sign,
  // the push's reverse): theta = atan2(-px, py).
  const double theta = std::atan2(-s * fx, s * fy);
  const double centi = std::fmod(theta * (18000.0 / kPi) + 36000.0, 36000.0);
  out.direction_centidegrees = static_cast<std::uint32_t>(std::lround(centi)) % 36000u;
  out.magnitude = std::min(size / max_force, 1.0);
  return out;
}

std::vector<std::uint8_t> pid_device_control(const PidLayout& p, PidControl command) {
  std::vector<std::uint8_t> r = report_of(p.control);
  const std::int32_t code = command == PidControl::EnableActuators    ? p.control_enable
                            : command == PidControl::DisableActuators ? p.control_disable
                            : command == PidControl::StopAllEffects   ? p.control_stop_all
                                                                      : p.control_reset;
  // A mask's bits are not a number in the field's logical range: written as is.
  write_hid_bits(r.data(), r.size(), p.control.bit, p.control.bits, code);
  return r;
}

std::vector<std::uint8_t> pid_device_gain(const PidLayout& p, double gain) {
  std::vector<std::uint8_t> r = report_of(p.device_gain);
  const double g = std::clamp(std::isfinite(gain) ? gain : 0.0, 0.0, 1.0);
  put(r, p.device_gain, std::llround(p.device_gain.min + g * (p.device_gain.max - p.device_gain.min)));
  return r;
}

std::vector<std::uint8_t> pid_create_constant_force(const PidLayout& p) {
  std::vector<std::uint8_t> r = report_of(p.create_type);
  // The selector's value for ET Constant Force in this report's own list.
  put(r, p.create_type, p.constant_force_type);
  return r;
}

std::vector<std::uint8_t> pid_block_load_request(const PidLayout& p) { return report_of(p.load_block); }

PidBlockLoad pid_parse_block_load(const PidLayout& p, const std::uint8_t* report, std::size_t size) {
  PidBlockLoad out;
  if (report == nullptr || size < p.load_block.report_bytes || size == 0 || report[0] != p.load_block.report_id)
    return out;
  const auto status = static_cast<std::int32_t>(
      read_hid_bits(report, size, p.load_status.bit, p.load_status.bits, p.load_status.min < 0));
  out.index = static_cast<std::int32_t>(
      read_hid_bits(report, size, p.load_block.bit, p.load_block.bits, p.load_block.min < 0));
  out.status = status == p.load_success ? PidLoadStatus::Success
               : status == p.load_full  ? PidLoadStatus::Full
               : status == p.load_error ? PidLoadStatus::Error
                                        : PidLoadStatus::Pending;
  if (out.status == PidLoadStatus::Success && (out.index < p.load_block.min || out.index > p.load_block.max))
    out.status = PidLoadStatus::Error;  // an index the device cannot mean
  return out;
}

std::vector<std::uint8_t> pid_set_constant_effect(const PidLayout& p, std::int32_t index, std::uint32_t duration_ms,
                                                  std::uint32_t direction_centidegrees) {
  std::vector<std::uint8_t> r = report_of(p.effect_block);
  put(r, p.effect_block, index);
  put(r, p.effect_type, p.constant_force_type);
  // The field's top value means "infinite" to some firmwares and a long
  // time to others: a finite duration never reaches it.
  put(r, p.duration, std::min<std::int64_t>(duration_ms, std::int64_t{p.duration.max} - 1));
  put(r, p.gain, p.gain.max);
  put(r, p.direction_enable, 1);
  const std::int64_t d = direction_centidegrees % 36000u;
  const PidSlot& dir = p.direction[0];
  put(r, dir, dir.min + d * (std::int64_t{dir.max} - dir.min) / 36000);
  return r;
}

std::vector<std::uint8_t> pid_set_constant_force(const PidLayout& p, std::int32_t index, double magnitude) {
  std::vector<std::uint8_t> r = report_of(p.magnitude);
  put(r, p.constant_block, index);
  const double m = std::clamp(std::isfinite(magnitude) ? magnitude : 0.0, -1.0, 1.0);
  const double end = m >= 0.0 ? p.magnitude.max : -static_cast<double>(p.magnitude.min);
  put(r, p.magnitude, std::llround(m * end));
  return r;
}

std::vector<std::uint8_t> pid_effect_start(const PidLayout& p, std::int32_t index, std::int32_t loops) {
  std::vector<std::uint8_t> r = report_of(p.operation);
  put(r, p.operation_block, index);
  put(r, p.operation, p.op_start);
  put(r, p.loop_count, loops);
  return r;
}

std::vector<std::uint8_t> pid_effect_stop(const PidLayout& p, std::int32_t index) {
  std::vector<std::uint8_t> r = report_of(p.operation);
  put(r, p.operation_block, index);
  put(r, p.operation, p.op_stop);
  put(r, p.loop_count, 1);
  return r;
}

std::vector<std::uint8_t> pid_block_free(const PidLayout& p, std::int32_t index) {
  std::vector<std::uint8_t> r = report_of(p.free_block);
  put(r, p.free_block, index);
  return r;
}

}  // namespace prox::devices
