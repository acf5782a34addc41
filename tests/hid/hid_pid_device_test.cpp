// Force-feedback devices (HID PID) through the C API, on emulated hidraw
// nodes made from the real OpenFFBoard and Arduino Joystick-with-FFB
// descriptors, with the real hidapi and a model of each firmware's effect
// blocks (emulated_pid.h): recognised from the descriptor, the host
// sequence byte for byte as ../shared/devices/pid/PROTOCOL.md gives it, the
// stick's position as the tool's, the contact force pushed back with each
// firmware's sign, the finite duration renewed (and lapsing when the host
// stops), Block Load's "full" and "error", unplug and reconnect, close.
#include "hid/emulated_pid.h"
#include "hid/hid_test_support.h"

#include "devices/hid_descriptor.h"
#include "support/marked_threads.h"

#include <algorithm>
#include <atomic>

using namespace prox::test;

namespace {

double steady_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Firmware {
  const char* name;
  std::uint16_t vid, pid;
  int slots;
  bool opposite;  // pushes the other way from DirectInput (PROTOCOL.md, section 7)
  // PROTOCOL.md's bytes: reset, stop all, enable; Create New Effect.
  Bytes reset, stop_all, enable, create;
  std::uint8_t block_load_id;
};

const Firmware kOpenFfb{"openffboard", 0x1209, 0xffb0, 40, false, {0x0c, 0x08}, {0x0c, 0x04}, {0x0c, 0x01},
                        {0x11, 0x01, 0x00, 0x00}, 0x12};
const Firmware kArduino{"arduino_ffb", 0x2341, 0x8036, 14, true, {0x0c, 0x04}, {0x0c, 0x03}, {0x0c, 0x01},
                        {0x05, 0x01, 0x00, 0x00}, 0x06};

// The stick's input report, deflected by dx, dy in [-1, 1], by the layout.
Bytes stick(const prox::devices::PidLayout& p, double dx, double dy) {
  const prox::devices::PidSlot& x = p.position[0];
  Bytes b(x.report_bytes, 0);
  b[0] = x.report_id;
  const auto put = [&](const prox::devices::PidSlot& s, double d) {
    if (s.present) prox::devices::write_hid_bits(b.data(), b.size(), s.bit, s.bits, std::lround(d * s.max));
  };
  put(x, dx);
  put(p.position[1], dy);
  return b;
}

class PidDevices : public HidScene, public ::testing::WithParamInterface<Firmware> {
 protected:
  // Plugs the firmware in with its model and opens it, holding the tool.
  void open(int pending = 0, int status = 0) {
    const Firmware& f = GetParam();
    EmulatedHidSpec spec = device_spec(f.name);
    model = EmulatedPid::attach(spec, f.slots);
    model->answer(pending, status);
    dev = bus.add(spec);
    proxHidDeviceDef def = def_for(f.vid, f.pid);
    def.maxForce = 4.0;
    ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &device));
  }
  void hold_the_tool() {
    ASSERT_OK(proxHidDevice_GetDeviceDef(device, &inner));
    proxDeviceDef d = proxDefaultDeviceDef();
    d.readPose = [](void* user, proxPose* pose) -> proxBool {
      prox::testing::mark_this_thread(true);
      const auto* in = static_cast<const proxDeviceDef*>(user);
      return in->readPose(in->userData, pose);
    };
    d.writeWrench = [](void* user, const proxWrench* w) {
      const auto* in = static_cast<const proxDeviceDef*>(user);
      in->writeWrench(in->userData, w);
    };
    d.userData = &inner;
    ASSERT_OK(proxBody_SetDevice(tool, &d));
  }
  // Sends the stick's report and waits until the device has read it.
  void deflect(double dx, double dy = 0.0) {
    const std::uint64_t before = stats_of(device).reportsRead;
    bus.send(dev, stick(model->layout(), dx, dy));
    ASSERT_TRUE(wait_until([&] { return stats_of(device).reportsRead > before; }));
  }
  double force_now() {
    proxWrench w{};
    EXPECT_OK(proxBody_GetWrench(tool, &w));
    return length(w.force);
  }

  std::shared_ptr<EmulatedPid> model;
  int dev = -1;
  proxHidDeviceId device{};
  proxDeviceDef inner{};
};

void PrintTo(const Firmware& f, std::ostream* os) { *os << f.name; }

}  // namespace

TEST(PidDevicesFound, AreRecognisedFromTheirDescriptors) {
  EmulatedHidBus bus;
  for (const char* name : {"openffboard", "arduino_ffb", "openffboard_1axis"}) bus.add(device_spec(name));
  int32_t count = 0;
  proxHidDeviceInfo infos[8];
  ASSERT_OK(proxEnumerateHidDevices(infos, 8, &count));
  // One entry a device (its joystick collection of the many a PID
  // descriptor has), told apart by their force axes.
  ASSERT_EQ(count, 3);
  EXPECT_EQ(infos[0].profile, PROX_HID_PID_JOYSTICK);
  EXPECT_EQ(infos[1].profile, PROX_HID_PID_JOYSTICK);
  EXPECT_EQ(infos[2].profile, PROX_HID_PID_WHEEL);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(infos[i].usagePage, 0x01);
    EXPECT_EQ(std::string(infos[i].path), bus.node(i));
  }
}

TEST_P(PidDevices, OpenRunsTheHostSequence) {
  const Firmware& f = GetParam();
  ASSERT_NO_FATAL_FAILURE(open(/*pending=*/3));  // Block Load is polled until it answers
  ASSERT_TRUE(wait_until([&] { return stats_of(device).forceEffect == PROX_HID_EFFECT_PLAYING; }));
  const std::vector<Bytes> w = bus.writes(dev);
  ASSERT_GE(w.size(), 8u);
  EXPECT_EQ(w[0], f.reset);
  EXPECT_EQ(w[1], f.reset);
  EXPECT_EQ(w[2], f.stop_all);
  EXPECT_EQ(w[3], f.enable);
  EXPECT_EQ(w[4], (Bytes{0x0d, 0xff}));  // full device gain
  const std::vector<Bytes> sent = bus.features_sent(dev);
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0], f.create);
  const std::vector<std::uint8_t> asked = bus.feature_requests(dev);
  EXPECT_EQ(std::count(asked.begin(), asked.end(), f.block_load_id), 4) << "three pending answers, then the block";
  // Set Effect of block 1, finite: 100 ms, renewed; then no force; then start.
  EXPECT_EQ(w[5][0], 0x01);
  EXPECT_EQ(w[5][1], 0x01);
  EXPECT_EQ(w[5][2], 0x01);                    // ET Constant Force
  EXPECT_EQ(w[5][3] | (w[5][4] << 8), 100);    // Duration, ms
  EXPECT_EQ(w[6], (Bytes{0x05, 0x01, 0x00, 0x00}));
  EXPECT_EQ(w[7], (Bytes{0x0a, 0x01, 0x01, 0x01}));
  const std::vector<EmulatedPid::Effect> e = model->effects();
  EXPECT_TRUE(e[0].allocated && e[0].set);
  EXPECT_EQ(e[0].duration_ms, 100u);
  EXPECT_TRUE(model->actuators_enabled());
  EXPECT_EQ(model->errors(), "");
  const proxHidDeviceStats s = stats_of(device);
  EXPECT_EQ(s.profile, PROX_HID_PID_JOYSTICK);
  EXPECT_EQ(s.effectsCreated, 1u);
  EXPECT_EQ(s.forceUpdates, 0u);
  // Closing stops and frees the effect and turns the actuators off.
  ASSERT_OK(proxHidDevice_Destroy(device));
  const std::vector<Bytes> after = bus.writes(dev);
  ASSERT_GE(after.size(), 4u);
  const std::size_t n = after.size();
  EXPECT_EQ(after[n - 4], (Bytes{0x0a, 0x01, 0x03, 0x01}));  // stop
  EXPECT_EQ(after[n - 3], (Bytes{0x0b, 0x01}));              // Block Free
  EXPECT_EQ(after[n - 2], f.stop_all);
  EXPECT_FALSE(model->actuators_enabled());
  EXPECT_FALSE(model->effects()[0].allocated);
  EXPECT_EQ(model->errors(), "");
}

TEST_P(PidDevices, TheStickIntoAWallIsPushedBackAndFreeSpaceSendsZero) {
  const Firmware& f = GetParam();
  ASSERT_NO_FATAL_FAILURE(open());
  ASSERT_NO_FATAL_FAILURE(hold_the_tool());
  proxThreadsDef td = proxDefaultThreadsDef();
  ASSERT_OK(proxWorld_StartThreads(world, &td));
  ASSERT_TRUE(wait_until([&] { return stats_of(device).forceEffect == PROX_HID_EFFECT_PLAYING; }));
  // Position control: 0.1 m of travel at full deflection; the tool starts
  // 30 mm from the wall. Gaps of 9, 8 and 7 mm (the force grows, short of
  // the world's maximum, which the face-to-face contact reaches by 5.5 mm),
  // then back out.
  double last = 0.0;
  for (const double gap : {0.009, 0.008, 0.007}) {
    SCOPED_TRACE(gap);
    ASSERT_NO_FATAL_FAILURE(deflect(-(0.03 - gap) / 0.1));
    EXPECT_NEAR(pose_of(device).position.x, kFar - (0.03 - gap), 1e-4);
    // The contact force settles (the safety gate ramps it), then what the
    // firmware renders settles on it, over the device's full scale (4 N).
    double settled = -1.0;
    ASSERT_TRUE(wait_until([&] {
      const double now = force_now();
      const bool still = std::fabs(now - settled) < 1e-6 && now > 0.0;
      settled = now;
      sleep_seconds(0.01);
      return still;
    }));
    double x = 0.0, y = 0.0;
    ASSERT_TRUE(wait_until([&] {
      model->push(steady_now(), f.opposite, &x, &y);
      return std::fabs(std::hypot(x, y) - settled / 4.0) < 2e-3;
    })) << "the device renders " << x << ", " << y << "; the contact asks " << settled / 4.0;
    EXPECT_GT(x, 0.0) << "pushed away from the wall (+x), with this firmware's sign";
    EXPECT_LT(std::fabs(y), 0.02 * x + 1e-3);
    EXPECT_GT(x, last + 0.01) << "nearer, harder";
    EXPECT_LT(x, 0.7) << "short of the world's maximum (3 N)";
    last = x;
  }
  EXPECT_GT(stats_of(device).forceUpdates, 2u);
  // Back in free space the force goes to zero.
  ASSERT_NO_FATAL_FAILURE(deflect(0.0));
  double x = 1.0, y = 1.0;
  ASSERT_TRUE(wait_until([&] {
    model->push(steady_now(), f.opposite, &x, &y);
    return x == 0.0 && y == 0.0 && stats_of(device).lastForceMagnitude == 0.0;
  })) << "the device renders " << x << ", " << y << ", the last magnitude sent "
      << stats_of(device).lastForceMagnitude << "; the tool's force " << force_now() << " N";
  ASSERT_OK(proxWorld_StopThreads(world));
  EXPECT_EQ(model->errors(), "");
  EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
#if !defined(__SANITIZE_THREAD__)
  EXPECT_EQ(prox::testing::marked_locks(), 0) << "the haptic thread locked a mutex";
#endif
}

TEST_P(PidDevices, TheEffectLapsesWhenTheHostStopsRenewingIt) {
  ASSERT_NO_FATAL_FAILURE(open());
  ASSERT_TRUE(wait_until([&] { return stats_of(device).forceEffect == PROX_HID_EFFECT_PLAYING; }));
  // Renewed while the device thread runs: its start moves on.
  const double first = model->effects()[0].started;
  ASSERT_TRUE(wait_until([&] { return model->effects()[0].started > first; }));
  EXPECT_TRUE(model->playing(steady_now()));
  // The device thread hangs in a write (as a host that dies would stop):
  // no renewal comes, and the effect stops on its own.
  bus.set_write_delay(dev, 2.0);
  ASSERT_TRUE(wait_until([&] { return !model->playing(steady_now()); }, 1.8))
      << "the effect outlived its host's renewals";
  bus.set_write_delay(dev, 0.0);
}

TEST_P(PidDevices, FullOrErrorLeavesAnInputOnlyStick) {
  for (const int status : {2, 3}) {
    SCOPED_TRACE(status);
    ASSERT_NO_FATAL_FAILURE(open(0, status));
    const proxHidForceEffect want = status == 2 ? PROX_HID_EFFECT_FULL : PROX_HID_EFFECT_ERROR;
    ASSERT_TRUE(wait_until([&] { return stats_of(device).forceEffect == want; }));
    ASSERT_NO_FATAL_FAILURE(deflect(0.5));
    EXPECT_NEAR(pose_of(device).position.x, kFar + 0.05, 1e-4) << "the stick still moves the tool";
    EXPECT_EQ(stats_of(device).effectsCreated, 0u);
    EXPECT_EQ(stats_of(device).forceUpdates, 0u);
    ASSERT_OK(proxHidDevice_Destroy(device));
    bus.unplug(dev);
  }
}

TEST_P(PidDevices, UnplugStopsAndAReconnectCreatesTheEffectAnew) {
  ASSERT_NO_FATAL_FAILURE(open());
  ASSERT_TRUE(wait_until([&] { return stats_of(device).forceEffect == PROX_HID_EFFECT_PLAYING; }));
  bus.unplug(dev);
  ASSERT_TRUE(wait_until([&] { return !stats_of(device).connected; }));
  EXPECT_EQ(stats_of(device).forceEffect, PROX_HID_EFFECT_STOPPED);
  bus.replug(dev);
  ASSERT_TRUE(wait_until([&] { return stats_of(device).effectsCreated == 2; }));
  EXPECT_EQ(stats_of(device).forceEffect, PROX_HID_EFFECT_PLAYING);
  EXPECT_EQ(model->creates(), 2);
  EXPECT_EQ(model->errors(), "");
}

// What the device renders stably is declared in its def, checked, and
// handed on in the def that attaches it (the tool's renderer reads it).
TEST_P(PidDevices, ItsDeclaredLimitsComeWithItsDeviceDef) {
  const Firmware& f = GetParam();
  EmulatedHidSpec spec = device_spec(f.name);
  model = EmulatedPid::attach(spec, f.slots);
  dev = bus.add(spec);
  proxHidDeviceDef def = def_for(f.vid, f.pid);
  def.maxStiffness = -5.0;
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &device), PROX_ERROR_INVALID_ARGUMENT, "maxStiffness");
  def.maxStiffness = 300.0;
  def.damping = 1.5;
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &device));
  proxDeviceDef d{};
  ASSERT_OK(proxHidDevice_GetDeviceDef(device, &d));
  EXPECT_EQ(d.maxStiffness, 300.0);
  EXPECT_EQ(d.damping, 1.5);
  EXPECT_OK(proxBody_SetDevice(tool, &d));
}

// A wheel base (OpenFFBoard's one-axis build): turned right by half its
// lock, the tool turns clockwise as its driver sees it (about the device
// frame's z, towards the user), by half the workspace's radians, about its
// reference point; its effect's direction is east for good.
TEST(PidWheel, TurnsTheToolAboutItsAxle) {
  EmulatedHidBus bus;
  EmulatedHidSpec spec = device_spec("openffboard_1axis");
  const std::shared_ptr<EmulatedPid> model = EmulatedPid::attach(spec, 40);
  const int dev = bus.add(spec);
  proxWorldDef wd = proxDefaultWorldDef();
  proxWorldId world{};
  ASSERT_OK(proxCreateWorld(&wd, &world));
  proxHidDeviceDef def = proxDefaultHidDeviceDef();
  def.referencePoint = {0.0, 0.1, 0.0};  // the tool turns about a point 10 cm above its origin
  def.workspace = 0.8;                   // rad at full lock
  proxHidDeviceId device{};
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &device));
  proxHidDeviceStats s{};
  ASSERT_TRUE(wait_until([&] {
    EXPECT_OK(proxHidDevice_GetStats(device, &s));
    return s.forceEffect == PROX_HID_EFFECT_PLAYING;
  }));
  EXPECT_EQ(s.profile, PROX_HID_PID_WHEEL);
  bus.send(dev, stick(model->layout(), 0.5, 0.0));
  ASSERT_TRUE(wait_until([&] {
    EXPECT_OK(proxHidDevice_GetStats(device, &s));
    return s.reportsRead > 0;
  }));
  proxPose p{};
  ASSERT_OK(proxHidDevice_GetPose(device, &p));
  // -0.4 rad about z: q = (cos 0.2, 0, 0, -sin 0.2); the origin, below the
  // reference point (0, 0.1, 0), swings clockwise about it, to the left:
  // (-0.1 sin 0.4, 0.1 - 0.1 cos 0.4, 0).
  EXPECT_NEAR(p.rotation.w, std::cos(0.2), 1e-4);
  EXPECT_NEAR(p.rotation.z, -std::sin(0.2), 1e-4);
  EXPECT_NEAR(p.position.x, -0.1 * std::sin(0.4), 1e-5);
  EXPECT_NEAR(p.position.y, 0.1 - 0.1 * std::cos(0.4), 1e-5);
  const std::vector<EmulatedPid::Effect> e = model->effects();
  EXPECT_EQ(e[0].direction, 9000);
  EXPECT_EQ(model->errors(), "");
  ASSERT_OK(proxWorld_Destroy(world));
}

INSTANTIATE_TEST_SUITE_P(Firmwares, PidDevices, ::testing::Values(kOpenFfb, kArduino),
                         [](const ::testing::TestParamInfo<Firmware>& i) {
                           return std::string(i.param.opposite ? "Arduino" : "OpenFFBoard");
                         });
