// The HID device's side for grounded force feedback (HID PID, hid_pid.h):
// recognised from its descriptor, its stick's position is the hand's
// (position control inside a workspace), and the wrench the haptic loop
// rendered becomes one constant-force effect (hid_pid_effect.h), all on the
// device's thread.
#include "devices/hid_device.h"

#include <hidapi.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

#if defined(__linux__)
#include <fcntl.h>
#include <linux/hidraw.h>
#include <sys/ioctl.h>
#include <unistd.h>
#endif

namespace prox::devices {
namespace {

// Firmwares whose push is the opposite of DirectInput's (the Arduino
// Joystick-with-FFB library computes +sin/-cos: ../shared/devices/pid/
// PROTOCOL.md, section 7). Which way a device pushes is its calibration,
// not its descriptor's: proxHidDeviceDef.forceSignX and forceSignY override it.
bool pushes_opposite(std::uint16_t vendor_id, std::uint16_t product_id) {
  return vendor_id == 0x2341 && product_id == 0x8036;  // Arduino Leonardo
}

// A position field as a deflection in [-1, 1] about its range's middle.
double deflection(const std::uint8_t* report, std::size_t size, const PidSlot& s) {
  const bool is_signed = s.min < 0;
  const double v = double(read_hid_bits(report, size, s.bit, s.bits, is_signed));
  const double mid = 0.5 * (double(s.min) + double(s.max)), half = 0.5 * (double(s.max) - double(s.min));
  if (!(half > 0.0)) return 0.0;
  return std::clamp((v - mid) / half, -1.0, 1.0);
}

}  // namespace

bool read_report_descriptor(const std::string& path, std::vector<std::uint8_t>& out) {
#if defined(__linux__)
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return false;
  int size = 0;
  bool ok = ::ioctl(fd, HIDIOCGRDESCSIZE, &size) >= 0 && size > 0 && size <= HID_MAX_DESCRIPTOR_SIZE;
  if (ok) {
    hidraw_report_descriptor d{};
    d.size = static_cast<std::uint32_t>(size);
    ok = ::ioctl(fd, HIDIOCGRDESC, &d) >= 0;
    if (ok) out.assign(d.value, d.value + size);
  }
  ::close(fd);
  return ok;
#else
  (void)path;
  (void)out;
  return false;
#endif
}

HidProfile pid_profile_of(const std::string& path) {
  std::vector<std::uint8_t> bytes;
  if (!read_report_descriptor(path, bytes)) return HidProfile::None;
  HidDescriptor d;
  PidLayout p;
  if (!parse_hid_descriptor(bytes.data(), bytes.size(), d) || !pid_layout_of(d, p) || !p.pid)
    return HidProfile::None;
  return p.axes == 1 ? HidProfile::PidWheel : HidProfile::PidJoystick;
}

void HidDevice::pid_open() {
  std::vector<std::uint8_t> bytes;
  HidDescriptor d;
  if (!read_report_descriptor(found_.path, bytes) || !parse_hid_descriptor(bytes.data(), bytes.size(), d) ||
      !pid_layout_of(d, pid_layout_) || !pid_layout_.pid)
    return;  // not a PID device after all: input only, as any unknown report
  PidEffectSettings e;
  e.max_force = settings_.max_force;
  const double known = pushes_opposite(found_.vendor_id, found_.product_id) ? -1.0 : 1.0;
  for (int k = 0; k < 2; ++k) e.sign[k] = settings_.force_sign[k] != 0 ? double(settings_.force_sign[k]) : known;
  pid_ = std::make_unique<PidEffect>(pid_layout_, e);
}

void HidDevice::pid_start(double now) {
  if (!pid_ || !handle_) return;
  if (pid_->start(handle_, now)) effects_created_.fetch_add(1, std::memory_order_relaxed);
  effect_state_.store(pid_->state(), std::memory_order_relaxed);
  outputs_written_.store(pid_->reports_written(), std::memory_order_relaxed);
  failed_writes_.store(pid_->failed_writes(), std::memory_order_relaxed);
}

// The stick's position report: the tool where the stick puts it. Any other
// report of the device (its PID State) carries no motion.
DecodeResult HidDevice::pid_input(const std::uint8_t* report, std::size_t size) {
  const PidSlot& x = pid_layout_.position[0];
  if (size == 0 || report[0] != x.report_id) return DecodeResult::Ignored;
  if (size != x.report_bytes) return DecodeResult::Malformed;
  const bool wheel = found_.profile == HidProfile::PidWheel;
  const double travel = settings_.workspace > 0.0 ? settings_.workspace : wheel ? 1.0 : 0.1;
  const double dx = deflection(report, size, x);
  const double dy = pid_layout_.position[1].present ? deflection(report, size, pid_layout_.position[1]) : 0.0;
  // Device frame: x right, y up, z towards the user. The stick's HID X is to
  // the right and its Y towards the user; a wheel turned right (X > 0) turns
  // clockwise as its driver sees it: about +z, negative.
  const double offset[3] = {wheel ? 0.0 : travel * dx, 0.0, wheel ? 0.0 : travel * dy};
  const double axle[3] = {0.0, 0.0, 1.0};
  motion_.place(home_, settings_.motion, offset, axle, wheel ? -travel * dx : 0.0);
  return DecodeResult::Decoded;
}

// The rendered wrench in the device's frame: a stick's force along its two
// axes (the component along the shaft dropped), or the torque about a
// wheel's axle.
void HidDevice::pid_outputs(double now) {
  if (!pid_ || !handle_) return;
  const runtime::DeviceWrench w = wrench_.load();
  const glm::dquat to_world(settings_.motion.device_to_world[0], settings_.motion.device_to_world[1],
                            settings_.motion.device_to_world[2], settings_.motion.device_to_world[3]);
  const glm::dquat to_device = glm::conjugate(glm::normalize(to_world));
  const glm::dvec3 f = to_device * glm::dvec3(w.force[0], w.force[1], w.force[2]);
  const glm::dvec3 t = to_device * glm::dvec3(w.torque[0], w.torque[1], w.torque[2]);
  const bool wheel = found_.profile == HidProfile::PidWheel;
  // A torque about +z turns the wheel towards -X, where a positive
  // magnitude at east pushes it.
  double fx = wheel ? -t.z : f.x, fy = wheel ? 0.0 : f.z;
  if (!std::isfinite(fx) || !std::isfinite(fy)) fx = fy = 0.0;  // the gate rules it out; never send one
  const std::uint64_t before = pid_->force_updates();
  if (!pid_->update(handle_, now, fx, fy)) return;
  outputs_written_.store(pid_->reports_written(), std::memory_order_relaxed);
  failed_writes_.store(pid_->failed_writes(), std::memory_order_relaxed);
  if (pid_->force_updates() != before) {
    force_updates_.fetch_add(pid_->force_updates() - before, std::memory_order_relaxed);
    const double m = pid_->last_magnitude();
    last_force_magnitude_.store(m, std::memory_order_relaxed);
    if (std::fabs(m) > max_force_magnitude_.load(std::memory_order_relaxed))
      max_force_magnitude_.store(std::fabs(m), std::memory_order_relaxed);  // the device thread's alone
  }
}

void HidDevice::pid_stop() {
  if (!pid_ || !handle_) return;
  pid_->stop(handle_);
  effect_state_.store(pid_->state(), std::memory_order_relaxed);
  outputs_written_.store(pid_->reports_written(), std::memory_order_relaxed);
  last_force_magnitude_.store(0.0, std::memory_order_relaxed);
}

}  // namespace prox::devices
