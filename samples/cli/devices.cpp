// proxima devices: the supported HID devices present; and the HID device
// behind `proxima run --device hid[:VVVV:PPPP]`.
#include "cli.h"

#if PROX_CLI_WITH_HID
#include <proxima/proxima_hid.h>
#endif

namespace proxcli {
namespace {

#if PROX_CLI_WITH_HID
const char* profile_name(proxHidProfile p) {
  switch (p) {
    case PROX_HID_SPACEMOUSE_SPLIT:
      return "spacemouse-split";
    case PROX_HID_SPACEMOUSE_COMBINED:
      return "spacemouse";
    case PROX_HID_DUALSHOCK4:
      return "dualshock4";
    case PROX_HID_DUALSENSE:
      return "dualsense";
    case PROX_HID_PID_JOYSTICK:
      return "pid-joystick";
    case PROX_HID_PID_WHEEL:
      return "pid-wheel";
    default:
      return "none";
  }
}

// proxHidForceEffect by name, as docs/devices.md has them.
const char* effect_name(proxHidForceEffect e) {
  switch (e) {
    case PROX_HID_EFFECT_PLAYING:
      return "playing";
    case PROX_HID_EFFECT_FULL:
      return "full";
    case PROX_HID_EFFECT_ERROR:
      return "error";
    case PROX_HID_EFFECT_NO_ANSWER:
      return "no answer";
    case PROX_HID_EFFECT_STOPPED:
      return "stopped";
    default:
      return "none";
  }
}

std::string hex4(uint16_t v) {
  char s[8];
  std::snprintf(s, sizeof s, "%04x", v);
  return s;
}

std::vector<proxHidDeviceInfo> enumerate() {
  int32_t count = 0;
  const proxResult asked = proxEnumerateHidDevices(nullptr, 0, &count);
  if (asked != PROX_ERROR_CAPACITY) check(asked);
  std::vector<proxHidDeviceInfo> infos(static_cast<std::size_t>(count) + 4);
  check(proxEnumerateHidDevices(infos.data(), static_cast<int32_t>(infos.size()), &count));
  infos.resize(static_cast<std::size_t>(count));
  return infos;
}

void pose_json(Json& j, const proxPose& p) {
  j.begin_array();
  for (double v :
       {p.position.x, p.position.y, p.position.z, p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z})
    j.value(v);
  j.end_array();
}
#endif

uint16_t parse_id(const std::string& text, const std::string& kind) {
  char* end = nullptr;
  const unsigned long v = std::strtoul(text.c_str(), &end, 16);
  if (text.size() != 4 || *end != '\0' || v > 0xffff)
    fail("--device: '" + kind + "' is not hid or hid:VVVV:PPPP (four hex digits each)");
  return static_cast<uint16_t>(v);
}

}  // namespace

#if PROX_CLI_WITH_HID
struct HidRun {
  proxHidDeviceId id{};
  proxHidDeviceInfo info{};
  proxPose first{};
  ~HidRun() { proxHidDevice_Destroy(id); }
};
#else
struct HidRun {};
#endif

bool is_hid_kind(const std::string& kind) { return kind == "hid" || kind.rfind("hid:", 0) == 0; }

int devices(Args& args) {
  std::string json_path;
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--json")
      json_path = args.next("--json file");
    else
      fail("devices: unknown option '" + opt + "'");
  }
#if PROX_CLI_WITH_HID
  const std::vector<proxHidDeviceInfo> found = enumerate();
  if (found.empty()) std::printf("no supported HID devices found\n");
  for (const proxHidDeviceInfo& d : found)
    std::printf("%s:%s  %-16s  %s  %s%s%s\n", hex4(d.vendorId).c_str(), hex4(d.productId).c_str(),
                profile_name(d.profile), d.name, d.path, d.serial[0] ? "  serial " : "", d.serial);
  if (!json_path.empty()) {
    Json j;
    j.begin_object();
    j.key("devices").begin_array();
    for (const proxHidDeviceInfo& d : found) {
      j.begin_object();
      j.key("vendor_id").value(hex4(d.vendorId));
      j.key("product_id").value(hex4(d.productId));
      j.key("profile").value(profile_name(d.profile));
      j.key("name").value(d.name);
      j.key("serial").value(d.serial);
      j.key("path").value(d.path);
      j.key("interface").value(d.interfaceNumber);
      j.key("usage_page").value(static_cast<int>(d.usagePage));
      j.key("usage").value(static_cast<int>(d.usage));
      j.end_object();
    }
    j.end_array();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return 0;
#else
  (void)json_path;
  fail("devices: this libproxima was built without HID devices (PROX_WITH_HIDAPI)");
#endif
}

std::shared_ptr<HidRun> open_hid(const std::string& kind, proxWorldId world, const proxPose& start,
                                 const proxVec3& reference, proxDeviceDef* def) {
  uint16_t vid = 0, pid = 0;
  if (kind != "hid") {
    const std::string ids = kind.substr(4);
    const auto colon = ids.find(':');
    if (colon == std::string::npos) fail("--device: '" + kind + "' is not hid or hid:VVVV:PPPP");
    vid = parse_id(ids.substr(0, colon), kind);
    pid = parse_id(ids.substr(colon + 1), kind);
  }
#if PROX_CLI_WITH_HID
  auto run = std::make_shared<HidRun>();
  proxHidDeviceDef d = proxDefaultHidDeviceDef();
  d.vendorId = vid, d.productId = pid;
  d.initialPose = start;
  d.referencePoint = reference;
  check(proxWorld_CreateHidDevice(world, &d, &run->id));
  run->first = start;
  for (const proxHidDeviceInfo& i : enumerate())
    if (i.vendorId == (vid ? vid : i.vendorId) && i.productId == (pid ? pid : i.productId)) {
      run->info = i;
      break;
    }
  check(proxHidDevice_GetDeviceDef(run->id, def));
  return run;
#else
  (void)world, (void)start, (void)reference, (void)def, (void)vid, (void)pid;
  fail("--device hid: this libproxima was built without HID devices (PROX_WITH_HIDAPI)");
#endif
}

#if PROX_CLI_WITH_HID
std::string hid_description(const HidRun& hid) {
  return std::string(profile_name(hid.info.profile)) + " " + hex4(hid.info.vendorId) + ":" +
         hex4(hid.info.productId) + " (" + hid.info.name + ") at " + hid.info.path;
}

void print_hid_stats(const HidRun& hid) {
  proxHidDeviceStats s;
  check(proxHidDevice_GetStats(hid.id, &s));
  std::printf(
      "hid: %llu reports read, %llu malformed; %llu outputs written, %llu failed; %llu disconnects, "
      "%llu reconnects\n",
      static_cast<unsigned long long>(s.reportsRead), static_cast<unsigned long long>(s.malformed),
      static_cast<unsigned long long>(s.outputsWritten), static_cast<unsigned long long>(s.failedWrites),
      static_cast<unsigned long long>(s.disconnects), static_cast<unsigned long long>(s.reconnects));
  if (s.profile == PROX_HID_PID_JOYSTICK || s.profile == PROX_HID_PID_WHEEL)
    std::printf("hid: force feedback: %llu effects created, %llu force updates, largest magnitude %.3f; effect %s\n",
                static_cast<unsigned long long>(s.effectsCreated), static_cast<unsigned long long>(s.forceUpdates),
                s.maxForceMagnitude, effect_name(s.forceEffect));
}

void hid_json(const HidRun& hid, Json& j) {
  proxHidDeviceStats s;
  check(proxHidDevice_GetStats(hid.id, &s));
  proxPose last;
  check(proxHidDevice_GetPose(hid.id, &last));
  auto count = [](uint64_t n) { return static_cast<long long>(n); };
  j.key("hid").begin_object();
  j.key("profile").value(profile_name(s.profile));
  j.key("vendor_id").value(hex4(hid.info.vendorId));
  j.key("product_id").value(hex4(hid.info.productId));
  j.key("path").value(hid.info.path);
  j.key("reports_read").value(count(s.reportsRead));
  j.key("malformed").value(count(s.malformed));
  j.key("outputs_written").value(count(s.outputsWritten));
  j.key("failed_writes").value(count(s.failedWrites));
  j.key("disconnects").value(count(s.disconnects));
  j.key("reconnects").value(count(s.reconnects));
  j.key("connected").value(s.connected != 0);
  j.key("force_updates").value(count(s.forceUpdates));
  j.key("effects_created").value(count(s.effectsCreated));
  j.key("max_force_magnitude").value(s.maxForceMagnitude);
  j.key("force_effect").value(effect_name(s.forceEffect));
  j.key("first_pose");
  pose_json(j, hid.first);
  j.key("last_pose");
  pose_json(j, last);
  j.end_object();
}
#else
std::string hid_description(const HidRun&) { return ""; }
void print_hid_stats(const HidRun&) {}
void hid_json(const HidRun&, Json&) {}
#endif

}  // namespace proxcli
