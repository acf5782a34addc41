// HID devices with the world's threads running: the outputs for an approach
// into contact and back out; unplugging mid-run (the force fades, the device
// is found again and resumes where it was); malformed reports and a flood;
// two devices at once; closing while the threads run; and that the haptic
// thread neither allocates nor locks with a HID device attached.
#include "hid/hid_test_support.h"
#include "support/marked_threads.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

using namespace prox::test;

namespace {

// Around the HID device's def: records on the haptic thread, into storage
// reserved before the threads start, the poses read and the forces handed.
struct Recorder {
  static constexpr int kCapacity = 30000;
  proxDeviceDef inner{};
  std::unique_ptr<double[]> force{new double[kCapacity]};
  std::atomic<int> wrenches{0};
  std::atomic<long> poses{0}, no_pose{0};
  std::atomic<double> last_x{0.0};

  proxDeviceDef def() {
    proxDeviceDef d = proxDefaultDeviceDef();
    d.readPose = [](void* user, proxPose* pose) -> proxBool {
      prox::testing::mark_this_thread(true);
      auto* self = static_cast<Recorder*>(user);
      if (!self->inner.readPose(self->inner.userData, pose)) {
        self->no_pose.fetch_add(1, std::memory_order_relaxed);
        return 0;
      }
      self->poses.fetch_add(1, std::memory_order_relaxed);
      self->last_x.store(pose->position.x, std::memory_order_relaxed);
      return 1;
    };
    d.writeWrench = [](void* user, const proxWrench* w) {
      auto* self = static_cast<Recorder*>(user);
      self->inner.writeWrench(self->inner.userData, w);
      const int i = self->wrenches.load(std::memory_order_relaxed);
      if (i < kCapacity)
        self->force[i] = length(w->force), self->wrenches.store(i + 1, std::memory_order_release);
    };
    d.userData = this;
    return d;
  }
  double last_force() const {
    const int n = wrenches.load(std::memory_order_acquire);
    return n > 0 ? force[n - 1] : 0.0;
  }
};

class HidThreads : public HidScene {
 protected:
  // Opens the first device with these ids and lets it hold the tool.
  proxHidDeviceId attach(std::uint16_t vid, std::uint16_t pid, double speed = 0.02,
                         double output_rate = 250.0) {
    proxHidDeviceDef def = def_for(vid, pid);
    def.linearSpeed = speed;
    def.outputRate = output_rate;
    proxHidDeviceId d{};
    EXPECT_OK(proxWorld_CreateHidDevice(world, &def, &d));
    EXPECT_OK(proxHidDevice_GetDeviceDef(d, &recorder.inner));
    const proxDeviceDef rd = recorder.def();
    EXPECT_OK(proxBody_SetDevice(tool, &rd));
    return d;
  }
  // Opens the first device with these ids and hands its def to the tool as
  // it comes, so the tool holds the device itself (the haptic loop hands it
  // the closest distance). A second tool far from everything holds the
  // recorder, around a device that stays put, so the haptic thread is still
  // marked and its ticks counted.
  proxHidDeviceId attach_direct(std::uint16_t vid, std::uint16_t pid, double speed,
                                double output_rate = 250.0) {
    proxHidDeviceDef def = def_for(vid, pid);
    def.linearSpeed = speed;
    def.outputRate = output_rate;
    proxHidDeviceId d{};
    EXPECT_OK(proxWorld_CreateHidDevice(world, &def, &d));
    proxDeviceDef dd{};
    EXPECT_OK(proxHidDevice_GetDeviceDef(d, &dd));
    EXPECT_OK(proxBody_SetDevice(tool, &dd));
    proxBodyDef bd = proxDefaultBodyDef();
    bd.mesh = mesh;
    bd.type = PROX_BODY_TOOL;
    bd.pose = kAside;
    EXPECT_OK(proxWorld_CreateBody(world, &bd, &aside));
    recorder.inner = proxDefaultDeviceDef();
    recorder.inner.readPose = [](void*, proxPose* pose) -> proxBool {
      *pose = kAside;
      return 1;
    };
    recorder.inner.writeWrench = [](void*, const proxWrench*) {};
    const proxDeviceDef rd = recorder.def();
    EXPECT_OK(proxBody_SetDevice(aside, &rd));
    EXPECT_OK(proxWorld_Step(world));
    return d;
  }
  // Waits (up to 5 s: the threads may be held up on a loaded machine) until
  // the last light bar colour written, at byte `at`, is `c` give or take one
  // step of rounding; the caller then checks it.
  void light_bar_settles(int dev, std::size_t at, const std::array<int, 3>& c) {
    wait_until(
        [&] {
          const std::vector<Bytes> w = bus.writes(dev);
          if (w.empty() || w.back().size() < at + 3) return false;
          for (int k = 0; k < 3; ++k)
            if (std::abs(int(w.back()[at + std::size_t(k)]) - c[std::size_t(k)]) > 1) return false;
          return true;
        },
        5.0);
  }
  // The force the haptic loop last rendered on the tool (N).
  double tool_force() {
    proxWrench w{};
    EXPECT_OK(proxBody_GetWrench(tool, &w));
    return length(w.force);
  }
  void start() {
    const proxThreadsDef t = proxDefaultThreadsDef();
    ASSERT_OK(proxWorld_StartThreads(world, &t));
  }
  // Holds `push` until the tool's x passes `x` (down to it when `down`), then sends `rest`.
  void drive_to(int dev, proxHidDeviceId d, const Bytes& push, const Bytes& rest, double x, bool down) {
    bus.send(dev, push);
    EXPECT_TRUE(wait_until([&] {
      const double at = pose_of(d).position.x;
      return down ? at <= x : at >= x;
    })) << "the tool is at "
        << pose_of(d).position.x;
    bus.send(dev, rest);
    EXPECT_TRUE(bus.drain(dev, 5.0));
  }
  // Brings the tool down to within `gap` of the wall's face (x at most
  // kWall + gap, and more than a tenth of `gap` from the face) with the
  // left stick of `report(stick)`, `rest` between moves. Closed loop, since
  // how late the device reads a report is up to the scheduler: each move
  // covers half the distance left, at a speed that a release half a second
  // late overshoots by at most that half plus 0.8 `gap`; a move that still
  // ends too close (a report read seconds late on a loaded machine) backs
  // the tool out to twice the gap and tries again, and `retreated_at` is
  // then the count of writes before the last retreat ended. `speed` is the
  // device's linearSpeed; the stick follows the profile's dead zone (0.1)
  // and squared response.
  template <typename Report>
  void approach_wall(int dev, proxHidDeviceId d, Report report, const Bytes& rest, double gap, double speed) {
    constexpr double kLate = 0.5;  // s
    const double target = kWall + gap;
    auto stick_for = [&](double v) {  // deflection m gives speed ((m - 0.1) / 0.9)^2
      const double m = 0.1 + 0.9 * std::sqrt(std::clamp(v / speed, 0.0, 1.0));
      return m * 127.5;
    };
    for (int move = 0; move < 40; ++move) {
      const double at = pose_of(d).position.x;
      approach_log += "at " + std::to_string(at) + "\n";
      if (at <= kWall + 0.1 * gap) {  // too close, or through: back out
        back_out(dev, d, report, rest, gap);
        continue;
      }
      const double left = at - target;
      if (left <= 0.0) return;
      const double stop_at = left > 0.1 * gap ? target + 0.5 * left : target;
      const double v = std::min(speed, (stop_at - target + 0.8 * gap) / kLate);
      // Towards the wall is below the centre (128).
      drive_to(dev, d, report(static_cast<std::uint8_t>(std::max(0.0, std::floor(128.0 - stick_for(v))))),
               rest, stop_at, true);
    }
    ADD_FAILURE() << "the tool did not reach " << gap << " m from the wall:\n" << approach_log;
  }
  // Backs the tool out to twice `gap` from the wall's face at a quarter of
  // `speed`; `retreated_at` is then the count of writes before it ended.
  template <typename Report>
  void back_out(int dev, proxHidDeviceId d, Report report, const Bytes& rest, double gap) {
    const double m = 0.1 + 0.9 * std::sqrt(0.25);  // the deflection for a quarter of the speed
    drive_to(dev, d, report(static_cast<std::uint8_t>(std::ceil(128.0 + m * 127.5))), rest, kWall + 2.0 * gap,
             false);
    retreated_at = bus.writes(dev).size();
  }
  // approach_wall, then the pose it settles at: a release read so late that
  // the tool ends inside the wall (seen on a loaded machine, beside a busy
  // core) backs it out and tries again, closed on where the tool is.
  template <typename Report>
  double settle_near_wall(int dev, proxHidDeviceId d, Report report, const Bytes& rest, double gap, double speed) {
    double at = kWall - 1.0;
    for (int attempt = 0; attempt < 10; ++attempt) {
      approach_wall(dev, d, report, rest, gap, speed);
      sleep_seconds(0.05);
      at = pose_of(d).position.x;
      if (at > kWall + 0.1 * gap) return at - kWall;
      approach_log += "settled at " + std::to_string(at) + ": backing out\n";
      back_out(dev, d, report, rest, gap);
    }
    return at - kWall;
  }
  void expect_haptic_thread_clean() {
    EXPECT_GT(recorder.poses.load() + recorder.no_pose.load(), 20);  // it ran
    EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
#if !defined(__SANITIZE_THREAD__)
    EXPECT_EQ(prox::testing::marked_locks(), 0) << "the haptic thread locked a mutex";
    // The interposition does see the library's locks: a game-thread call takes some.
    prox::testing::mark_this_thread(true);
    stats_of(device);
    prox::testing::mark_this_thread(false);
    EXPECT_GT(prox::testing::marked_locks(), 0);
    prox::testing::reset_marked_counts();
#endif
  }

  static constexpr double kWall = 0.1;  // the wall's face: the tool's gap is its x less this
  static constexpr proxPose kAside{{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  std::string approach_log;  // where each move of approach_wall began
  std::size_t retreated_at = 0;
  Recorder recorder;
  proxHidDeviceId device{};
  proxBodyId aside{};
};

}  // namespace

// The light bar's colour at the closest distance d, from the mapping
// docs/devices.md documents: green at rest (no contact, or d at or beyond
// the cutoff), red at or inside the safety distance, and in between green
// blended linearly towards amber (255, 160, 0) as d falls from the cutoff.
static std::array<int, 3> documented_colour(double d) {
  if (d <= kSafety) return {255, 0, 0};
  if (d >= kCutoff) return {0, 255, 0};
  const double t = (kCutoff - d) / (kCutoff - kSafety);
  return {int(std::lround(255.0 * t)), int(std::lround(255.0 + (160.0 - 255.0) * t)), 0};
}

// The DualSense's rumble, trigger resistance and light bar for an approach
// in stops (8, 5, 2 mm from the wall, then 0.7 mm: inside the safety
// distance) and back out to 2 cm: nothing while far; the rumble and trigger
// rising with the force; the light bar's colour at each stop that of the
// distance the tool is held at, never going back on the way in; back to
// rest after.
TEST_F(HidThreads, OutputsFollowTheForceAndTheDistanceIntoContactAndBackOut) {
  const int dev = bus.add(device_spec("dualsense"));
  // 25 outputs a second at most: slower than the force changes, so the limit binds.
  device = attach_direct(0x054c, 0x0ce6, 0.04, 25.0);
  start();
  sleep_seconds(0.3);
  EXPECT_TRUE(bus.writes(dev).empty()) << "outputs while far from everything";
  const Bytes centre = dualsense_report(128, 128, 128, 128);
  for (const double gap : {0.008, 0.005, 0.002, 0.0007}) {
    // The cubes' faces are parallel: the gap is the tool's x less the wall's.
    const double d = settle_near_wall(
        dev, device, [](std::uint8_t x) { return dualsense_report(x, 128, 128, 128); }, centre, gap, 0.04);
    ASSERT_GT(d, 0.0) << "the tool stopped too late, inside the wall:\n" << approach_log;
    const std::array<int, 3> c = documented_colour(d);
    light_bar_settles(dev, 45, c);
    const std::vector<Bytes> w = bus.writes(dev);
    ASSERT_FALSE(w.empty()) << "nothing written at " << d << " m";
    EXPECT_NEAR(w.back()[45], c[0], 1) << "red at " << d << " m";
    EXPECT_NEAR(w.back()[46], c[1], 1) << "green at " << d << " m";
    EXPECT_EQ(w.back()[47], c[2]) << "blue at " << d << " m";
  }
  const double felt = tool_force();
  EXPECT_GT(felt, 0.05);
  const std::vector<Bytes> in = bus.writes(dev);
  ASSERT_FALSE(in.empty());
  // Monotone since the last retreat (approach_wall), if there was one.
  ASSERT_LE(retreated_at, in.size());
  int last = 0, last_red = 0, last_green = 255;
  for (std::size_t i = retreated_at; i < in.size(); ++i) {
    const Bytes& w = in[i];
    ASSERT_EQ(w.size(), 48u);
    ASSERT_EQ(w[0], 0x02);
    EXPECT_GE(int(w[3]), last) << "the rumble fell while approaching";
    last = w[3];
    EXPECT_EQ(w[3], w[4]);
    EXPECT_GE(int(w[45]), last_red) << "the light bar's red fell while approaching";
    EXPECT_LE(int(w[46]), last_green) << "the light bar's green rose while approaching";
    last_red = w[45], last_green = w[46];
  }
  const Bytes& near = in.back();
  // 3 N is full: the rumble and the trigger's resistance are the force's share of it.
  EXPECT_NEAR(near[3], felt / 3.0 * 255.0, 3.0);
  EXPECT_EQ(near[11], 0x01);  // constant resistance
  EXPECT_NEAR(near[13], felt / 3.0 * 255.0, 3.0);
  // Back out, beyond the cutoff.
  drive_to(dev, device, dualsense_report(255, 128, 128, 128), centre, kWall + 0.02, false);
  ASSERT_TRUE(wait_until([&] { return tool_force() == 0.0; }));
  sleep_seconds(0.1);
  const std::vector<Bytes> all = bus.writes(dev);
  ASSERT_GT(all.size(), in.size());
  const Bytes& rest = all.back();
  EXPECT_EQ(rest[3], 0);
  EXPECT_EQ(rest[4], 0);
  EXPECT_EQ(rest[11], 0x05);  // trigger effect off
  EXPECT_EQ(rest[13], 0);
  EXPECT_EQ(rest[45], 0);  // the rest colour: green
  EXPECT_EQ(rest[46], 255);
  EXPECT_EQ(rest[47], 0);
  // Only when it changed: no two consecutive writes alike.
  for (std::size_t i = 1; i < all.size(); ++i) EXPECT_NE(all[i], all[i - 1]) << i;
  const proxHidDeviceStats s = stats_of(device);
  EXPECT_EQ(s.outputsWritten, all.size());
  EXPECT_EQ(s.failedWrites, 0u);
  // At most 25 a second: writes at least 40 ms apart on the device's
  // thread. Here they are seen as they arrive, each late by up to a
  // scheduling delay (on a loaded machine, 16 ms was seen), so n writes
  // span at least (n - 1) 40 ms less that delay; unlimited, a change would
  // be written every few milliseconds and a few writes would span no time.
  const std::vector<double> t = bus.write_times(dev);
  ASSERT_GT(t.size(), 3u);
  constexpr double kArrivalJitter = 0.025;
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = i + 1; j < t.size(); ++j)
      ASSERT_GE(t[j] - t[i], 0.040 * double(j - i) - kArrivalJitter) << "writes " << i << " to " << j;
  ASSERT_OK(proxWorld_StopThreads(world));
  expect_haptic_thread_clean();
}

// A device that takes half a second to answer each write holds up only its
// own thread: the haptic loop keeps its rate, game-thread calls return at
// once, and closing waits for the one write under way at most.
TEST_F(HidThreads, ADeviceThatStopsAnsweringWritesBlocksNothingElse) {
  const int dev = bus.add(device_spec("dualsense"));
  device = attach(0x054c, 0x0ce6);
  start();
  bus.set_write_delay(dev, 0.5);
  drive_to(dev, device, dualsense_report(0, 128, 128, 128), dualsense_report(128, 128, 128, 128),
           kFar - 0.0235, true);
  ASSERT_TRUE(wait_until([&] { return !bus.writes(dev).empty(); }));  // one write is hanging now
  const long before = recorder.poses.load();
  const double t0 = proxGetTime();
  sleep_seconds(0.3);
  const double ticked = double(recorder.poses.load() - before) / (proxGetTime() - t0);
  EXPECT_GT(ticked, 300.0) << "haptic ticks a second while a write hangs";
  const double s0 = proxGetTime();
  stats_of(device);
  EXPECT_LT(proxGetTime() - s0, 0.05);
  const double c0 = proxGetTime();
  ASSERT_OK(proxHidDevice_Close(device));
  EXPECT_LT(proxGetTime() - c0, 0.6);
  ASSERT_OK(proxWorld_StopThreads(world));
  EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
#if !defined(__SANITIZE_THREAD__)
  EXPECT_EQ(prox::testing::marked_locks(), 0) << "the haptic thread locked a mutex";
#endif
}

// The DualShock 4's rumble and light bar: held 4 mm from the wall, then at
// 0.7 mm, then back out.
TEST_F(HidThreads, DualShock4RumbleAndLightBarFollowTheDistance) {
  const int dev = bus.add(device_spec("ds4v2"));
  device = attach_direct(0x054c, 0x09cc, 0.04);
  start();
  const Bytes centre = ds4_report(128, 128, 128, 128);
  for (const double gap : {0.004, 0.0007}) {
    const double d = settle_near_wall(
        dev, device, [](std::uint8_t x) { return ds4_report(x, 128, 128, 128); }, centre, gap, 0.04);
    ASSERT_GT(d, 0.0) << "the tool stopped too late, inside the wall:\n" << approach_log;
    const std::array<int, 3> c = documented_colour(d);
    light_bar_settles(dev, 6, c);
    const std::vector<Bytes> w = bus.writes(dev);
    ASSERT_FALSE(w.empty());
    ASSERT_EQ(w.back().size(), 32u);
    EXPECT_EQ(w.back()[0], 0x05);
    EXPECT_EQ(w.back()[1], 0x03);
    EXPECT_NEAR(w.back()[6], c[0], 1) << "red at " << d << " m";
    EXPECT_NEAR(w.back()[7], c[1], 1) << "green at " << d << " m";
    EXPECT_EQ(w.back()[8], c[2]) << "blue at " << d << " m";
  }
  const double felt = tool_force();
  std::vector<Bytes> w = bus.writes(dev);
  EXPECT_NEAR(w.back()[5], felt / 3.0 * 255.0, 3.0);
  drive_to(dev, device, ds4_report(255, 128, 128, 128), centre, kWall + 0.02, false);
  ASSERT_TRUE(wait_until([&] { return tool_force() == 0.0; }));
  sleep_seconds(0.1);
  w = bus.writes(dev);
  EXPECT_EQ(w.back()[4], 0);
  EXPECT_EQ(w.back()[5], 0);
  EXPECT_EQ(w.back()[6], 0);
  EXPECT_EQ(w.back()[7], 255);
  EXPECT_EQ(w.back()[8], 0);
  ASSERT_OK(proxWorld_StopThreads(world));
  expect_haptic_thread_clean();
}

TEST_F(HidThreads, UnplugFadesAndReconnectResumesWhereItWas) {
  const int dev = bus.add(device_spec("ds4v2"));
  device = attach(0x054c, 0x09cc);
  start();
  const Bytes centre = ds4_report(128, 128, 128, 128);
  drive_to(dev, device, ds4_report(0, 128, 128, 128), centre, kFar - 0.0235, true);
  sleep_seconds(0.3);
  ASSERT_GT(recorder.last_force(), 0.05);
  // Through the recorder's callbacks the distance is not known: the light
  // bar follows the force (docs/devices.md).
  const std::vector<Bytes> w = bus.writes(dev);
  ASSERT_FALSE(w.empty());
  EXPECT_GT(w.back()[5], 0);
  EXPECT_EQ(w.back()[6], w.back()[5]);
  EXPECT_EQ(w.back()[7], 255 - w.back()[5]);
  const proxPose held = pose_of(device);
  bus.unplug(dev);
  ASSERT_TRUE(wait_until([&] { return !stats_of(device).connected; }));
  // No pose: the gate fades the force out.
  ASSERT_TRUE(wait_until([&] { return recorder.last_force() == 0.0; }));
  const long missing = recorder.no_pose.load();
  EXPECT_GT(missing, 0);
  EXPECT_EQ(stats_of(device).disconnects, 1u);
  bus.replug(dev);
  ASSERT_TRUE(wait_until([&] { return stats_of(device).connected; }, 5.0));
  const proxHidDeviceStats s = stats_of(device);
  EXPECT_EQ(s.reconnects, 1u);
  const proxPose back = pose_of(device);
  EXPECT_EQ(back.position.x, held.position.x);
  EXPECT_EQ(back.position.y, held.position.y);
  EXPECT_EQ(back.position.z, held.position.z);
  // The force comes back, and the device answers again at its new node.
  ASSERT_TRUE(wait_until([&] { return recorder.last_force() > 0.05; }));
  const std::uint64_t read = stats_of(device).reportsRead;
  bus.send(dev, ds4_report(128, 130, 128, 128));
  ASSERT_TRUE(wait_until([&] { return stats_of(device).reportsRead > read; }));
  ASSERT_OK(proxWorld_StopThreads(world));
  expect_haptic_thread_clean();
}

TEST_F(HidThreads, MalformedReportsAreCountedAndAFloodIsReadWhole) {
  const int dev = bus.add(device_spec("dualsense"));
  device = attach(0x054c, 0x0ce6);
  start();
  Bytes shorter(10, 0), longer(65, 0), unknown(64, 0);
  shorter[0] = 0x01, longer[0] = 0x01, unknown[0] = 0x31;
  bus.send(dev, shorter);
  bus.send(dev, longer);
  bus.send(dev, unknown);
  ASSERT_TRUE(bus.drain(dev, 5.0));
  ASSERT_TRUE(wait_until([&] { return stats_of(device).malformed == 3; }));
  EXPECT_EQ(stats_of(device).reportsRead, 0u);
  EXPECT_NEAR(pose_of(device).position.x, kFar, 1e-15);
  // 5,000 reports queued at once: every one read, each on its own.
  const int kFlood = 5000;
  const double t0 = proxGetTime();
  for (int i = 0; i < kFlood; ++i) bus.send(dev, dualsense_report(128, 128, 128, 128));
  ASSERT_TRUE(bus.drain(dev, 30.0));
  ASSERT_TRUE(wait_until([&] { return stats_of(device).reportsRead == std::uint64_t(kFlood); }));
  const double seconds = proxGetTime() - t0;
  std::printf("flood: %d reports read in %.3f s (%.0f a second)\n", kFlood, seconds, kFlood / seconds);
  EXPECT_EQ(stats_of(device).malformed, 3u);
  EXPECT_LT(stats_of(device).lastReportAge, 1.0);
  ASSERT_OK(proxWorld_StopThreads(world));
  expect_haptic_thread_clean();
}

TEST_F(HidThreads, TwoDevicesAtOnce) {
  const int pad = bus.add(device_spec("ds4v2"));
  const int puck = bus.add(device_spec("spacenavigator"));
  // Fast enough that a report read late under a loaded machine still moves each visibly.
  device = attach(0x054c, 0x09cc, 0.1);
  proxHidDeviceDef def = def_for(0x046d, 0xc626);
  def.linearSpeed = 0.1;
  proxHidDeviceId other;
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &other));
  start();
  bus.send(pad, ds4_report(128, 128, 128, 128, 0, 255));  // R2: up
  bus.send(puck, puck_split(1, 0, 350, 0));               // towards the user: +z
  sleep_seconds(0.15);
  bus.send(pad, ds4_report(128, 128, 128, 128));
  bus.send(puck, puck_split(1, 0, 0, 0));
  ASSERT_TRUE(bus.drain(pad, 5.0));
  ASSERT_TRUE(bus.drain(puck, 5.0));
  ASSERT_TRUE(
      wait_until([&] { return stats_of(device).reportsRead == 2 && stats_of(other).reportsRead == 2; }));
  const proxPose a = pose_of(device), b = pose_of(other);
  EXPECT_GT(a.position.y, 0.001);
  EXPECT_NEAR(a.position.z, 0.0, 1e-15);
  EXPECT_GT(b.position.z, 0.001);
  EXPECT_NEAR(b.position.y, 0.0, 1e-15);
  // The haptic loop follows the one holding the tool.
  ASSERT_TRUE(wait_until([&] { return std::fabs(recorder.last_x.load() - a.position.x) < 1e-12; }));
  ASSERT_OK(proxWorld_StopThreads(world));
  expect_haptic_thread_clean();
}

TEST_F(HidThreads, ClosedWhileTheThreadsRun) {
  const int dev = bus.add(device_spec("spacemouse_wireless"));
  device = attach(0x256f, 0xc62e);
  start();
  bus.send(dev, puck_combined(100, 0, 0, 0, 0, 0));
  ASSERT_TRUE(wait_until([&] { return recorder.poses.load() > 50; }));
  ASSERT_OK(proxHidDevice_Close(device));
  const long before = recorder.no_pose.load();
  ASSERT_TRUE(wait_until([&] { return recorder.no_pose.load() > before + 50; }));
  // A closed device is refused for a tool, and its id everywhere.
  ASSERT_OK(proxWorld_StopThreads(world));
  proxDeviceDef dd;
  EXPECT_FAILS(proxHidDevice_GetDeviceDef(device, &dd), PROX_ERROR_INVALID_HANDLE, "closed");
  const proxDeviceDef stale = recorder.inner;
  EXPECT_FAILS(proxBody_SetDevice(tool, &stale), PROX_ERROR_INVALID_ARGUMENT, "HID device");
  EXPECT_EQ(prox::testing::marked_allocations(), 0);
}

TEST_F(HidThreads, AnotherWorldsDeviceIsRefusedAndDestroyingTheWorldClosesIt) {
  bus.add(device_spec("ds4v2"));
  proxHidDeviceDef def = def_for(0, 0);
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &device));
  proxDeviceDef dd;
  ASSERT_OK(proxHidDevice_GetDeviceDef(device, &dd));
  proxWorldDef wd = proxDefaultWorldDef();
  proxWorldId second;
  ASSERT_OK(proxCreateWorld(&wd, &second));
  proxBodyDef bd = proxDefaultBodyDef();
  bd.mesh = proxMeshId{};
  proxMeshDef md = proxDefaultMeshDef();
  md.positions = positions.data();
  md.vertexCount = 8;
  md.indices = indices.data();
  md.triangleCount = 12;
  proxMeshId m;
  ASSERT_OK(proxWorld_CreateMesh(second, &md, &m));
  bd.mesh = m;
  bd.type = PROX_BODY_TOOL;
  proxBodyId t;
  ASSERT_OK(proxWorld_CreateBody(second, &bd, &t));
  EXPECT_FAILS(proxBody_SetDevice(t, &dd), PROX_ERROR_INVALID_ARGUMENT, "another world");
  ASSERT_OK(proxWorld_Destroy(second));
  ASSERT_OK(proxWorld_Destroy(world));
  proxHidDeviceStats s;
  EXPECT_EQ(proxHidDevice_GetStats(device, &s), PROX_ERROR_INVALID_HANDLE);
}
