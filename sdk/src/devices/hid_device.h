// A HID device through hidapi (docs/devices.md#hid-devices). Its own thread
// reads the reports (with a short timeout, so it also writes between them),
// decodes them, integrates the tool's pose and publishes it through a
// seqlock; the haptic loop reads that pose and stores the wrench it rendered
// in another seqlock, from which the device thread builds the outputs, at
// most output_rate a second and only when they change. The haptic thread
// never calls hidapi, never waits, never allocates.
#pragma once

#include "devices/hid_motion.h"
#include "devices/hid_output.h"
#include "devices/hid_pid_effect.h"
#include "devices/hid_profiles.h"
#include "runtime/device.h"
#include "runtime/handoff.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

struct hid_device_;

namespace prox::devices {

// A supported device hidapi sees now.
struct HidFound {
  std::uint16_t vendor_id = 0, product_id = 0;
  HidProfile profile = HidProfile::None;
  int interface_number = -1;
  std::uint16_t usage_page = 0, usage = 0;
  std::string name, serial, path;
};

// Every supported device present (one entry per device: its motion
// collection). Any thread; serialised with the other hidapi calls that
// touch hidapi's global state.
std::vector<HidFound> enumerate_hid_devices();

// A hidraw node's report descriptor (Linux: HIDIOCGRDESC); false when it
// cannot be read.
bool read_report_descriptor(const std::string& path, std::vector<std::uint8_t>& out);
// The profile a joystick or gamepad collection has from its descriptor: a
// HID PID device with one or two force axes, or None.
HidProfile pid_profile_of(const std::string& path);

struct HidDeviceSettings {
  std::string path;  // or empty: the first supported device with these ids (0: any)
  std::uint16_t vendor_id = 0, product_id = 0;
  MotionSettings motion;
  OutputSettings output;
  double output_rate = 250.0;  // Hz
  double initial_position[3] = {0, 0, 0};
  double initial_rotation[4] = {1, 0, 0, 0};
  double reference_local[3] = {0, 0, 0};
  double reconnect_interval = 1.0;  // s between searches while unplugged
  // Grounded force feedback (HID PID): the tool's travel at full deflection
  // (m; rad for a wheel; 0: 0.1 m, or 1 rad), the force at full magnitude
  // (N; N m for a wheel) and the sign each device axis takes (0: the
  // firmware's known convention).
  double workspace = 0.0;
  double max_force = 5.0;
  int force_sign[2] = {0, 0};
  runtime::DeviceLimits limits;  // what it renders stably (none by default)
};

struct HidStats {
  HidProfile profile = HidProfile::None;
  bool connected = false;
  std::uint64_t reports_read = 0, malformed = 0, outputs_written = 0, failed_writes = 0;
  std::uint64_t disconnects = 0, reconnects = 0, pose_reads = 0, no_pose_ticks = 0;
  double last_report_age = -1.0;  // s
  // HID PID devices.
  std::uint64_t force_updates = 0, effects_created = 0;
  double last_force_magnitude = 0.0;  // [-1, 1]
  double max_force_magnitude = 0.0;   // [0, 1]
  PidEffectState effect = PidEffectState::None;
};

class HidDevice final : public runtime::HapticDevice {
 public:
  // Finds and opens the device, reads its calibration and starts its
  // thread; null with *error set when there is none or it will not open.
  static std::unique_ptr<HidDevice> open(const HidDeviceSettings& settings, std::string* error);
  ~HidDevice();
  HidDevice(const HidDevice&) = delete;
  HidDevice& operator=(const HidDevice&) = delete;

  // Stops the thread and closes the device; from then on there is no pose.
  void close() override;
  bool closed() const { return closed_.load(std::memory_order_acquire); }

  // The haptic thread's side.
  bool read_pose(runtime::DevicePose* pose) override;
  void write_wrench(const runtime::DeviceWrench& wrench) override;
  runtime::DeviceLimits limits() const override { return settings_.limits; }

  HidStats stats() const;
  // The pose last integrated (valid or not).
  runtime::DevicePose pose() const { return published_.load().pose; }
  const HidFound& found() const { return found_; }

 private:
  struct Published {
    runtime::DevicePose pose;
    bool valid;
  };

  HidDevice(const HidDeviceSettings& settings, const HidFound& found, hid_device_* handle);
  void run();
  void read_calibration();
  bool reopen();
  void disconnect();
  void publish(bool valid);
  void write_outputs(double now);
  // HID PID (hid_pid_device.cpp): the layout, read at open; the effect,
  // started on the device thread at each (re)connection; the stick's
  // position as the tool's; the wrench as the effect's force.
  void pid_open();
  void pid_start(double now);
  DecodeResult pid_input(const std::uint8_t* report, std::size_t size);
  void pid_outputs(double now);
  void pid_stop();

  HidDeviceSettings settings_;
  HidFound found_;
  // The device thread's own.
  hid_device_* handle_ = nullptr;
  HidInput input_;
  HidAxes axes_;
  MotionCalibration calibration_;
  ToolMotion motion_;
  OutputReport last_output_;
  double last_step_ = 0.0, last_output_time_ = -1e9, next_search_ = 0.0;
  bool recentre_held_ = false;
  PidLayout pid_layout_;
  std::unique_ptr<PidEffect> pid_;
  ToolMotion home_;  // where a position-controlled tool is with the stick at rest
  // Shared.
  runtime::SeqLock<Published> published_;           // device thread -> haptic, game
  runtime::SeqLock<runtime::DeviceWrench> wrench_;  // haptic -> device thread
  std::atomic<bool> stop_{false}, closed_{false}, connected_{false};
  std::atomic<std::uint64_t> reports_read_{0}, malformed_{0}, outputs_written_{0}, failed_writes_{0};
  std::atomic<std::uint64_t> disconnects_{0}, reconnects_{0}, pose_reads_{0}, no_pose_ticks_{0};
  std::atomic<double> last_report_time_{-1.0};
  std::atomic<std::uint64_t> force_updates_{0}, effects_created_{0};
  std::atomic<double> last_force_magnitude_{0.0}, max_force_magnitude_{0.0};
  std::atomic<PidEffectState> effect_state_{PidEffectState::None};
  std::thread thread_;
};

}  // namespace prox::devices
