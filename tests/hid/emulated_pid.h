// A HID PID firmware's side of the reports, for the emulated bus
// (emulated_hid.h): effect blocks that Create New Effect takes and Block
// Free or a Device Control Reset gives back, Block Load and PID Pool
// answered by report id (they share one ioctl number), and every output
// report parsed against the device's own layout, as
// ../shared/devices/pid/PROTOCOL.md (section 9) says an emulation must. A
// model of the device, for tests: what the host sent is checked against it.
#pragma once

#include "hid/emulated_hid.h"

#include "devices/hid_pid.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace prox::test {

class EmulatedPid {
 public:
  // The layout from the spec's descriptor (a test fails when it has none);
  // `slots` effect blocks (OpenFFBoard 40, the Arduino library 14).
  static std::shared_ptr<EmulatedPid> attach(EmulatedHidSpec& spec, int slots);

  // What Block Load answers next: `pending` times "pending" (status 0)
  // first, then the block it took, or `status` when not 0 (2 full, 3 error).
  void answer(int pending, int status);

  struct Effect {
    bool allocated = false;
    bool set = false;             // a Set Effect came for it
    std::uint32_t duration_ms = 0;
    std::int64_t direction = 0;   // the field's value
    std::int64_t magnitude = 0;   // the field's value
    double started = -1.0;        // steady-clock seconds of the last Start
    bool stopped = false;
  };

  // Snapshots, any thread.
  std::vector<Effect> effects() const;
  int creates() const;
  bool actuators_enabled() const;
  // Whether an effect is playing at `now` (steady-clock seconds): started,
  // not stopped, and within its duration since its last start.
  bool playing(double now) const;
  // The protocol errors seen: an index the device never gave, a Set Effect
  // before any Create, a Device Control in the wrong encoding. Empty when
  // the host behaved.
  std::string errors() const;
  const devices::PidLayout& layout() const { return layout_; }

  // The force the device would render now, as its firmware computes it: x
  // to the right, y towards the user, in fractions of full scale.
  // DirectInput's push (OpenFFBoard) or the opposite (`opposite`, the
  // Arduino library).
  void push(double now, bool opposite, double* x, double* y) const;

 private:
  void set_feature(const Bytes& report);
  bool get_feature(std::uint8_t id, Bytes& reply);
  void output(const Bytes& report);
  std::int64_t field(const Bytes& r, const devices::PidSlot& s) const;

  devices::PidLayout layout_;
  mutable std::mutex mutex_;
  std::vector<Effect> effects_;
  int pending_ = 0, status_ = 0, last_created_ = 0, last_status_ = 0, creates_ = 0, polls_left_ = 0;
  bool created_any_ = false, enabled_ = false;
  std::string errors_;
};

}  // namespace prox::test
