// HID devices through the C API, on emulated hidraw nodes made from the
// real descriptors, with the real hidapi: enumeration of every profile, its
// calibration read at open, motion from each profile's axes, the rate
// integration and the re-centre button, misuse, and the outputs written
// for an approach into contact and back out.
#include "hid/hid_test_support.h"

#include <algorithm>
#include <cstring>

using namespace prox::test;

namespace {

struct Expected {
  const char* name;
  std::uint16_t vid, pid;
  proxHidProfile profile;
  int interface_number;
  std::uint16_t usage;
};

const Expected kDevices[] = {
    {"spacenavigator", 0x046d, 0xc626, PROX_HID_SPACEMOUSE_SPLIT, 0, 0x08},
    {"spacemouse_wireless", 0x256f, 0xc62e, PROX_HID_SPACEMOUSE_COMBINED, 0, 0x08},
    {"ds4v2", 0x054c, 0x09cc, PROX_HID_DUALSHOCK4, 3, 0x05},
    {"dualsense", 0x054c, 0x0ce6, PROX_HID_DUALSENSE, 3, 0x05},
};

std::vector<proxHidDeviceInfo> enumerate() {
  int32_t count = 0;
  const proxResult asked = proxEnumerateHidDevices(nullptr, 0, &count);
  EXPECT_EQ(asked, count == 0 ? PROX_SUCCESS : PROX_ERROR_CAPACITY);
  std::vector<proxHidDeviceInfo> infos(std::size_t(count) + 1);
  EXPECT_OK(proxEnumerateHidDevices(infos.data(), int32_t(infos.size()), &count));
  infos.resize(std::size_t(count));
  return infos;
}

class HidCapi : public HidScene {};

}  // namespace

TEST_F(HidCapi, EnumeratesEveryProfileOnceWithItsCollection) {
  EXPECT_TRUE(enumerate().empty());
  for (const Expected& e : kDevices) bus.add(device_spec(e.name));
  const std::vector<proxHidDeviceInfo> infos = enumerate();
  ASSERT_EQ(infos.size(), 4u);  // the SpaceNavigator's two vendor collections are left out
  for (std::size_t i = 0; i < 4; ++i) {
    const Expected& e = kDevices[i];
    const proxHidDeviceInfo& f = infos[i];
    SCOPED_TRACE(e.name);
    EXPECT_EQ(f.vendorId, e.vid);
    EXPECT_EQ(f.productId, e.pid);
    EXPECT_EQ(f.profile, e.profile);
    EXPECT_EQ(f.usagePage, 0x01);
    EXPECT_EQ(f.usage, e.usage);
    EXPECT_EQ(f.interfaceNumber, e.interface_number);
    EXPECT_EQ(std::string(f.path), bus.node(int(i)));
    EXPECT_EQ(std::string(f.serial), device_spec(e.name).serial);
    EXPECT_NE(std::string(f.name).find(device_spec(e.name).product), std::string::npos) << f.name;
  }
  // Too small an array: the count says how big.
  proxHidDeviceInfo two[2];
  int32_t count = 0;
  EXPECT_FAILS(proxEnumerateHidDevices(two, 2, &count), PROX_ERROR_CAPACITY, "4 devices");
  EXPECT_EQ(count, 4);
  EXPECT_FAILS(proxEnumerateHidDevices(nullptr, 1, &count), PROX_ERROR_INVALID_ARGUMENT, "infos");
  EXPECT_FAILS(proxEnumerateHidDevices(two, -1, &count), PROX_ERROR_INVALID_ARGUMENT, "capacity");
  EXPECT_FAILS(proxEnumerateHidDevices(two, 2, nullptr), PROX_ERROR_INVALID_ARGUMENT, "count");
}

TEST_F(HidCapi, PadsHaveTheirCalibrationReadAtOpen) {
  const int ds4 = bus.add(device_spec("ds4v2"));
  const int ds = bus.add(device_spec("dualsense"));
  const int puck = bus.add(device_spec("spacemouse_wireless"));
  proxHidDeviceId a, b, c;
  proxHidDeviceDef def = def_for(0x054c, 0x09cc);
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &a));
  def = def_for(0x054c, 0x0ce6);
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &b));
  def = def_for(0x256f, 0);
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &c));
  EXPECT_EQ(bus.feature_requests(ds4), std::vector<std::uint8_t>{0x02});
  EXPECT_EQ(bus.feature_requests(ds), std::vector<std::uint8_t>{0x05});
  EXPECT_TRUE(bus.feature_requests(puck).empty());
  EXPECT_EQ(stats_of(a).profile, PROX_HID_DUALSHOCK4);
  EXPECT_EQ(stats_of(b).profile, PROX_HID_DUALSENSE);
  EXPECT_EQ(stats_of(c).profile, PROX_HID_SPACEMOUSE_COMBINED);
  EXPECT_TRUE(stats_of(a).connected);
}

TEST_F(HidCapi, OpenRefusesWhatIsNotThere) {
  proxHidDeviceId d;
  proxHidDeviceDef def = def_for(0x054c, 0x09cc);
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_FILE, "054c:09cc");
  bus.add(device_spec("ds4v2"));
  def.path = "/dev/hidraw99";
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_FILE, "/dev/hidraw99");
  def = def_for(0, 0);
  def.deadZone = 0.95;
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_INVALID_ARGUMENT, "deadZone");
  def = def_for(0, 0);
  def.outputRate = 1000;
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_INVALID_ARGUMENT, "outputRate");
  def = def_for(0, 0);
  def.linearSpeed = std::nan("");
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_INVALID_ARGUMENT, "linearSpeed");
  def = def_for(0, 0);
  def.deviceToWorld = {0, 0, 0, 0};
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_INVALID_ARGUMENT, "deviceToWorld");
  proxHidDeviceDef raw{};
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &raw, &d), PROX_ERROR_INVALID_ARGUMENT,
               "proxDefaultHidDeviceDef");
  def = def_for(0, 0);
  def.apiVersion = PROX_API_VERSION + 1;  // made by a newer minor version's header
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, &def, &d), PROX_ERROR_VERSION_MISMATCH, "proxDefaultHidDeviceDef");
  def = def_for(0, 0);
  EXPECT_FAILS(proxWorld_CreateHidDevice(proxWorldId{}, &def, &d), PROX_ERROR_INVALID_HANDLE, "world");
  EXPECT_FAILS(proxWorld_CreateHidDevice(world, nullptr, &d), PROX_ERROR_INVALID_ARGUMENT, "def");
  // Bad ids everywhere.
  proxHidDeviceStats s;
  proxDeviceDef dd;
  EXPECT_FAILS(proxHidDevice_GetStats(proxHidDeviceId{0, 0, world}, &s), PROX_ERROR_INVALID_HANDLE, "null");
  EXPECT_FAILS(proxHidDevice_GetDeviceDef(proxHidDeviceId{7, 0, world}, &dd), PROX_ERROR_INVALID_HANDLE,
               "HID");
  EXPECT_FAILS(proxHidDevice_Close(proxHidDeviceId{1, 0, world}), PROX_ERROR_INVALID_HANDLE, "HID");
  // From another thread.
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &d));
  proxResult other = PROX_SUCCESS;
  std::thread([&] { other = proxHidDevice_GetStats(d, &s); }).join();
  EXPECT_EQ(other, PROX_ERROR_WRONG_THREAD);
  EXPECT_OK(proxHidDevice_Close(d));
  EXPECT_FAILS(proxHidDevice_GetStats(d, &s), PROX_ERROR_INVALID_HANDLE, "closed");
  EXPECT_FAILS(proxHidDevice_Close(d), PROX_ERROR_INVALID_HANDLE, "closed");
  // proxWorld_OpenHidDevice, the deprecated name, opens the same way.
  ASSERT_OK(proxWorld_OpenHidDevice(world, &def, &d));
  EXPECT_TRUE(proxHidDevice_IsValid(d));
  EXPECT_OK(proxHidDevice_Destroy(d));
  EXPECT_FAILS(proxWorld_OpenHidDevice(world, &raw, &d), PROX_ERROR_INVALID_ARGUMENT, "proxDefaultHidDeviceDef");
}

// Each profile's axes move the tool the documented way: a full deflection
// of one axis, held, moves it along (or turns it about) the world axis the
// mapping names, at the configured speed.
TEST_F(HidCapi, EachProfileMovesTheToolAlongItsMappedAxis) {
  struct Case {
    const char* name;
    Bytes push, rest;
    int axis;     // world axis: 0 x, 1 y, 2 z
    double sign;  // the direction it moves
  };
  const Case cases[] = {
      {"spacenavigator", puck_split(1, 350, 0, 0), puck_split(1, 0, 0, 0), 0, +1.0},  // right: +x
      {"spacemouse_wireless", puck_combined(0, 0, 350, 0, 0, 0), puck_combined(0, 0, 0, 0, 0, 0), 1,
       -1.0},                                                                              // pressed: -y
      {"ds4v2", ds4_report(128, 255, 128, 128), ds4_report(128, 128, 128, 128), 2, +1.0},  // stick down: +z
      {"dualsense", dualsense_report(128, 128, 128, 128, 0, 255), dualsense_report(128, 128, 128, 128), 1,
       +1.0},  // R2: +y
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const int dev = bus.add(device_spec(c.name));
    proxHidDeviceDef def = proxDefaultHidDeviceDef();
    def.path = nullptr;
    const EmulatedHidSpec spec = device_spec(c.name);
    def.vendorId = spec.vendor_id, def.productId = spec.product_id;
    def.linearSpeed = 0.2;
    proxHidDeviceId d;
    ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &d));
    const proxPose p0 = pose_of(d);
    const double t0 = proxGetTime();
    bus.send(dev, c.push);
    sleep_seconds(0.2);
    bus.send(dev, c.rest);
    ASSERT_TRUE(bus.drain(dev, 5.0));
    ASSERT_TRUE(wait_until([&] { return stats_of(d).reportsRead >= 2; }));
    const double held = proxGetTime() - t0;
    const proxPose p1 = pose_of(d);
    const double moved[3] = {p1.position.x - p0.position.x, p1.position.y - p0.position.y,
                             p1.position.z - p0.position.z};
    // About 0.2 m/s for about 0.2 s: between half and the whole held time.
    EXPECT_GT(moved[c.axis] * c.sign, 0.2 * 0.1);
    EXPECT_LT(moved[c.axis] * c.sign, 0.2 * held + 1e-9);
    for (int k = 0; k < 3; ++k) {
      if (k != c.axis) {
        EXPECT_NEAR(moved[k], 0.0, 1e-12) << k;
      }
    }
    EXPECT_NEAR(p1.rotation.w, 1.0, 1e-12);
    EXPECT_EQ(stats_of(d).malformed, 0u);
    ASSERT_OK(proxHidDevice_Close(d));
  }
}

TEST_F(HidCapi, RotationTurnsAboutTheReferencePoint) {
  const int dev = bus.add(device_spec("spacemouse_wireless"));
  proxHidDeviceDef def = def_for(0x256f, 0xc62e);
  def.angularSpeed = 2.0;
  proxHidDeviceId d;
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &d));
  bus.send(dev, puck_combined(0, 0, 0, 0, 0, -350));  // about the puck's z (down), backwards: about world +y
  sleep_seconds(0.15);
  bus.send(dev, puck_combined(0, 0, 0, 0, 0, 0));
  ASSERT_TRUE(bus.drain(dev, 5.0));
  ASSERT_TRUE(wait_until([&] { return stats_of(d).reportsRead >= 2; }));
  const proxPose p = pose_of(d);
  // A turn about +y: only w and y in the quaternion.
  const double angle = 2.0 * std::atan2(p.rotation.y, p.rotation.w);
  EXPECT_GT(angle, 0.1);
  EXPECT_NEAR(p.rotation.x, 0.0, 1e-12);
  EXPECT_NEAR(p.rotation.z, 0.0, 1e-12);
  // The reference point (0.05, 0.05, 0.05 in the tool) did not move.
  const double c = std::cos(angle), s = std::sin(angle);
  const double rx = c * 0.05 + s * 0.05, rz = -s * 0.05 + c * 0.05;
  EXPECT_NEAR(p.position.x + rx, kFar + 0.05, 1e-9);
  EXPECT_NEAR(p.position.y + 0.05, 0.05, 1e-9);
  EXPECT_NEAR(p.position.z + rz, 0.05, 1e-9);
}

TEST_F(HidCapi, DeadZoneHoldsStillAndRecentreReturnsToTheStart) {
  const int dev = bus.add(device_spec("ds4v2"));
  proxHidDeviceDef def = def_for(0x054c, 0x09cc);
  def.deadZone = 0.2;
  proxHidDeviceId d;
  ASSERT_OK(proxWorld_CreateHidDevice(world, &def, &d));
  // Within the dead zone: (150 - 128) / 127 = 0.17 on every axis.
  bus.send(dev, ds4_report(150, 150, 150, 150, 40, 0));
  sleep_seconds(0.1);
  ASSERT_TRUE(bus.drain(dev, 5.0));
  proxPose p = pose_of(d);
  EXPECT_NEAR(p.position.x, kFar, 1e-15);
  EXPECT_NEAR(p.position.y, 0.0, 1e-15);
  EXPECT_NEAR(p.position.z, 0.0, 1e-15);
  EXPECT_EQ(p.rotation.w, 1.0);
  // Past it: moves.
  bus.send(dev, ds4_report(255, 128, 0, 128));
  sleep_seconds(0.1);
  bus.send(dev, ds4_report(128, 128, 128, 128));
  ASSERT_TRUE(bus.drain(dev, 5.0));
  ASSERT_TRUE(wait_until([&] { return stats_of(d).reportsRead >= 3; }));
  p = pose_of(d);
  EXPECT_GT(p.position.x, kFar + 0.002);
  EXPECT_LT(p.rotation.w, 1.0);
  // Options: back to the start.
  bus.send(dev, ds4_report(128, 128, 128, 128, 0, 0, true));
  ASSERT_TRUE(bus.drain(dev, 5.0));
  ASSERT_TRUE(wait_until([&] { return std::fabs(pose_of(d).position.x - kFar) < 1e-15; }));
  p = pose_of(d);
  EXPECT_NEAR(p.position.y, 0.0, 1e-15);
  EXPECT_EQ(p.rotation.w, 1.0);
}
