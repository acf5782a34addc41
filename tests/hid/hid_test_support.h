// What the HID C API tests share: the emulated bus with the real devices,
// the C API tests' scene of two 10 cm cubes (the wall at the origin, the
// tool beside it along +x, beyond the cutoff), reports built from the
// layouts, and waiting.
#pragma once

#include <proxima/proxima.h>
#include <proxima/proxima_hid.h>

#include <gtest/gtest.h>

#include "capi/expect.h"
#include "capi/two_cubes.h"
#include "hid/emulated_hid.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

namespace prox::test {

inline bool wait_until(const std::function<bool()>& done, double seconds = 10.0) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return done();
}

inline void sleep_seconds(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

inline EmulatedHidSpec device_spec(const std::string& name) {
  return shared_device(PROX_SHARED_DEVICES_DIR, name);
}

// Reports, by the layouts: a pad's input report 0x01 with the sticks and
// triggers given and nothing pressed.
inline Bytes ds4_report(std::uint8_t lx, std::uint8_t ly, std::uint8_t rx, std::uint8_t ry,
                        std::uint8_t l2 = 0, std::uint8_t r2 = 0, bool options = false) {
  Bytes b(64, 0);
  b[0] = 0x01, b[1] = lx, b[2] = ly, b[3] = rx, b[4] = ry;
  b[5] = 0x08;  // hat released
  b[6] = options ? 0x20 : 0x00;
  b[8] = l2, b[9] = r2;
  return b;
}
inline Bytes dualsense_report(std::uint8_t lx, std::uint8_t ly, std::uint8_t rx, std::uint8_t ry,
                              std::uint8_t l2 = 0, std::uint8_t r2 = 0, bool options = false) {
  Bytes b(64, 0);
  b[0] = 0x01, b[1] = lx, b[2] = ly, b[3] = rx, b[4] = ry, b[5] = l2, b[6] = r2;
  b[8] = 0x08;
  b[9] = options ? 0x20 : 0x00;
  return b;
}
inline void put16(Bytes& b, std::size_t at, int v) {
  b[at] = std::uint8_t(v & 0xff), b[at + 1] = std::uint8_t((v >> 8) & 0xff);
}
// SpaceMouse Wireless: report 1 with all six axes.
inline Bytes puck_combined(int x, int y, int z, int rx, int ry, int rz) {
  Bytes b(13, 0);
  b[0] = 0x01;
  const int v[6] = {x, y, z, rx, ry, rz};
  for (int i = 0; i < 6; ++i) put16(b, std::size_t(1 + 2 * i), v[i]);
  return b;
}
// SpaceNavigator: report 1 (translation) or 2 (rotation).
inline Bytes puck_split(std::uint8_t id, int a, int b_, int c) {
  Bytes b(7, 0);
  b[0] = id;
  put16(b, 1, a), put16(b, 3, b_), put16(b, 5, c);
  return b;
}
inline Bytes puck_buttons(std::uint8_t bits) { return {0x03, bits, 0x00}; }

inline double length(const proxVec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// The scene's cutoff and safety distance (m): capi_test::TwoCubes's.
inline constexpr double kCutoff = 0.01, kSafety = 0.001;

// The C API's world of two cubes; the tool starts at x = kFar (3 cm from
// the wall, beyond the 1 cm cutoff).
class HidScene : public capi_test::TwoCubes {
 protected:
  static constexpr double kFar = 0.13;

  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(create_scene(kFar));
    ASSERT_OK(proxWorld_Step(world));
  }
  void TearDown() override {
    if (proxWorld_IsValid(world)) proxWorld_StopThreads(world);
    TwoCubes::TearDown();
  }

  static proxPose start_pose() { return {{kFar, 0, 0}, {1, 0, 0, 0}}; }

  // A def for the first device with these ids, starting where the tool is.
  static proxHidDeviceDef def_for(std::uint16_t vid, std::uint16_t pid) {
    proxHidDeviceDef d = proxDefaultHidDeviceDef();
    d.vendorId = vid, d.productId = pid;
    d.initialPose = start_pose();
    d.referencePoint = {0.05, 0.05, 0.05};
    return d;
  }

  proxPose pose_of(proxHidDeviceId d) {
    proxPose p{};
    EXPECT_OK(proxHidDevice_GetPose(d, &p));
    return p;
  }
  proxHidDeviceStats stats_of(proxHidDeviceId d) {
    proxHidDeviceStats s{};
    EXPECT_OK(proxHidDevice_GetStats(d, &s));
    return s;
  }

  EmulatedHidBus bus;
};

}  // namespace prox::test
