// A headless OpenXR app for the tests, as an integrator writes one: it owns
// the instance, the session, the world space and an action set into which
// Proxima's actions are merged; it polls events (forwarding session states
// to the XR device), syncs actions and runs the frame loop on the test's
// thread, which is also the Proxima world's game thread. Through Debian's
// loader with the core validation layer; the runtime is the mock's
// (mock_runtime.cpp), whose control panel the test holds.
#pragma once

#include <proxima/proxima_openxr.h>

#include "openxr/mock_control.h"

#include <functional>
#include <string>

namespace prox::test {

// The mock runtime's control panel (loads the runtime library, which stays
// loaded for the test's life).
const ProxMockXrControl& mock_control();

struct XrAppOptions {
  bool timespec = true;  // enable XR_KHR_convert_timespec_time
  uint32_t habits = 0;   // the mock runtime's PROX_MOCK_XR_HABIT_*
};

class XrApp {
 public:
  explicit XrApp(const XrAppOptions& options = {});
  ~XrApp();
  XrApp(const XrApp&) = delete;
  XrApp& operator=(const XrApp&) = delete;

  // One frame: poll events (forwarding each state, and each event's time
  // when it has one, to `device` when set), then, while the session runs,
  // wait, begin, sync, OnFrame and end; headless as XR_MND_headless allows
  // once a wait returns no display time: no frame calls from then on, a
  // sync and a sleep of a 90 Hz frame.
  void frame();
  // Frames until done() or `seconds` pass; whether done() became true.
  bool pump_until(const std::function<bool()>& done, double seconds = 20.0);
  void pump_for(double seconds);

  // Hands the device over (and, when the app knows one, "now" as the
  // runtime's time: see runtime_now).
  void set_device(proxXrDeviceId device);
  // The newest event time advanced by the app's monotonic clock since it
  // was polled: a headless app's clock on a runtime with no other; 0 before
  // any event had a time.
  XrTime runtime_now() const;
  proxXrDeviceDef device_def() const;
  // Ends the session (xrRequestExitSession, then the frames until EXITING).
  void exit_session();
  // Destroys the session and everything in it, then the instance.
  void destroy();

  XrInstance instance = XR_NULL_HANDLE;
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction appAction = XR_NULL_HANDLE;  // the app's own (a left-hand pose), bound beside Proxima's
  XrAction pose = XR_NULL_HANDLE, haptic = XR_NULL_HANDLE;
  XrPath right = XR_NULL_PATH;
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  bool running = false;
  int syncsNotFocused = 0;
  bool frameCalls = true;     // false once xrWaitFrame gave no display time
  XrTime lastEventTime = 0;   // the newest event time > 0
  double lastEventPolled = 0;  // when (steady clock, s)
  std::string validationLog;        // the core validation layer's output file
  std::size_t validationStart = 0;  // its size when this app began

 private:
  bool timespec_;
  proxXrDeviceId device_{};
};

// Fails the test (and says where) when an OpenXR call fails.
void xr_check(XrResult r, const char* what);
// What the validation layer wrote, or "" when it raised nothing.
std::string validation_errors(const XrApp& app);

}  // namespace prox::test
