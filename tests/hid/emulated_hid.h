// An emulated HID bus for the tests: hidraw nodes made by umockdev from the
// real report descriptors, answering the ioctls hidapi's hidraw backend asks
// (HIDIOCGRDESCSIZE, HIDIOCGRDESC, feature reports), handing over one report
// per read, capturing every write and feature report, and unplugging on
// request. A mock of the kernel's hidraw driver only: hidapi and everything
// above it are real. The process must run under umockdev-wrapper (the
// preload) for hidapi in it to see the nodes; children started with
// child_environment() see them too.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace prox::test {

using Bytes = std::vector<std::uint8_t>;

struct EmulatedHidSpec {
  std::uint16_t vendor_id = 0, product_id = 0;
  int interface_number = 0;
  std::uint16_t bcd_device = 0x0100;
  std::string manufacturer, product, serial;
  Bytes descriptor;                        // the real report descriptor
  std::map<std::uint8_t, Bytes> features;  // get-feature replies by report id (byte 0 = id)
  // A device with a model of its own behind its reports (a PID device's
  // effect blocks, emulated_pid.h), called under the bus's lock: each
  // set-feature report; each get-feature request by id, filling the reply
  // (false: not this model's, `features` answers); each output report.
  std::function<void(const Bytes& report)> on_set_feature;
  std::function<bool(std::uint8_t id, Bytes& reply)> on_get_feature;
  std::function<void(const Bytes& report)> on_output;
};

// The devices of ../shared/devices, by name: "spacenavigator",
// "spacemouse_wireless", "ds4v2", "dualsense", and the force-feedback ones
// of its pid/ folder, "openffboard", "openffboard_1axis", "arduino_ffb"
// (their PID model is emulated_pid.h's to attach). `devices_dir` holds the
// .rdesc.bin files. Fails the calling test when one is missing.
EmulatedHidSpec shared_device(const std::string& devices_dir, const std::string& name);

class EmulatedHidBus {
 public:
  // `in_process`: hidapi runs in this process, which must then be under the
  // preload (a test fails otherwise); false for a bus only children use.
  explicit EmulatedHidBus(bool in_process = true);
  ~EmulatedHidBus();
  EmulatedHidBus(const EmulatedHidBus&) = delete;
  EmulatedHidBus& operator=(const EmulatedHidBus&) = delete;

  // Plugs a device in as /dev/hidrawN (N = the returned index).
  int add(const EmulatedHidSpec& spec);
  std::string node(int device) const;

  // Queues an input report; the device hands one report per read, the next
  // only once the previous one was read.
  void send(int device, const Bytes& report);
  // Reports queued and not yet read.
  std::size_t pending(int device);
  // Waits until every queued report was read; false after `seconds`.
  bool drain(int device, double seconds);

  // Everything written to the device so far (output reports, byte 0 = id).
  std::vector<Bytes> writes(int device);
  // When each write arrived (s, on the steady clock), in order.
  std::vector<double> write_times(int device);
  // The ids of the feature reports asked for, in order.
  std::vector<std::uint8_t> feature_requests(int device);
  // Set-feature reports received.
  std::vector<Bytes> features_sent(int device);
  // Makes writes take this long (s) from now on: a device that stops answering.
  void set_write_delay(int device, double seconds);

  // Unplugs the device: reads, writes and ioctls on open handles fail
  // (ENODEV) and enumeration no longer finds it.
  void unplug(int device);
  // Plugs it back in at the same node, with the same strings and serial.
  void replug(int device);
  bool plugged(int device);

  // The environment a child process needs to see the bus: UMOCKDEV_DIR and
  // the preload ("NAME=value" strings).
  std::vector<std::string> child_environment() const;
  std::string root_dir() const;

 private:
  struct Device;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace prox::test
