#include "devices/hid_device.h"

#include <hidapi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cwchar>
#include <mutex>

namespace prox::devices {
namespace {

// hidapi keeps its global error and its initialisation in globals: every
// call that touches them (init, enumerate, open) goes through this lock, on
// device and game threads only.
std::mutex& hidapi_mutex() {
  static std::mutex m;
  return m;
}

bool hidapi_ready() {
  static bool ok = hid_init() == 0;  // under hidapi_mutex() at first use
  return ok;
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string utf8(const wchar_t* w) {
  std::string s;
  if (!w) return s;
  for (; *w; ++w) {
    const auto c = static_cast<std::uint32_t>(*w);
    if (c < 0x80) {
      s += char(c);
    } else if (c < 0x800) {
      s += char(0xc0 | (c >> 6)), s += char(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
      s += char(0xe0 | (c >> 12)), s += char(0x80 | ((c >> 6) & 0x3f)), s += char(0x80 | (c & 0x3f));
    } else {
      s += char(0xf0 | (c >> 18)), s += char(0x80 | ((c >> 12) & 0x3f)), s += char(0x80 | ((c >> 6) & 0x3f)),
          s += char(0x80 | (c & 0x3f));
    }
  }
  return s;
}

// Under hidapi_mutex().
std::vector<HidFound> enumerate_locked() {
  std::vector<HidFound> out;
  if (!hidapi_ready()) return out;
  hid_device_info* list = hid_enumerate(0, 0);
  for (const hid_device_info* i = list; i; i = i->next) {
    HidProfile p = hid_profile_of(
        i->vendor_id, i->product_id, i->usage_page, i->usage,
        i->bus_type == HID_API_BUS_USB || i->bus_type == HID_API_BUS_UNKNOWN ? i->interface_number : -1);
    // A joystick or gamepad collection of no known device: a force-feedback
    // device when its descriptor has the PID reports (read once a node: a
    // PID descriptor has many top-level collections, each listed).
    if (p == HidProfile::None && i->path && i->usage_page == 0x01 && (i->usage == 0x04 || i->usage == 0x05)) {
      const bool seen = std::any_of(out.begin(), out.end(), [&](const HidFound& f) { return f.path == i->path; });
      if (!seen) p = pid_profile_of(i->path);
    }
    if (p == HidProfile::None || !i->path) continue;
    HidFound f;
    f.vendor_id = i->vendor_id, f.product_id = i->product_id, f.profile = p;
    f.interface_number = i->interface_number, f.usage_page = i->usage_page, f.usage = i->usage;
    const std::string maker = utf8(i->manufacturer_string), product = utf8(i->product_string);
    f.name = maker.empty() ? product : product.empty() ? maker : maker + " " + product;
    f.serial = utf8(i->serial_number);
    f.path = i->path;
    out.push_back(std::move(f));
  }
  hid_free_enumeration(list);
  return out;
}

}  // namespace

std::vector<HidFound> enumerate_hid_devices() {
  std::lock_guard<std::mutex> lock(hidapi_mutex());
  return enumerate_locked();
}

std::unique_ptr<HidDevice> HidDevice::open(const HidDeviceSettings& settings, std::string* error) {
  std::lock_guard<std::mutex> lock(hidapi_mutex());
  if (!hidapi_ready()) {
    *error = "hidapi could not be initialised (hid_init failed)";
    return nullptr;
  }
  const std::vector<HidFound> all = enumerate_locked();
  const HidFound* pick = nullptr;
  for (const HidFound& f : all) {
    const bool match = !settings.path.empty()
                           ? f.path == settings.path
                           : (settings.vendor_id == 0 || f.vendor_id == settings.vendor_id) &&
                                 (settings.product_id == 0 || f.product_id == settings.product_id);
    if (match) {
      pick = &f;
      break;
    }
  }
  if (!pick) {
    char ids[32];
    std::snprintf(ids, sizeof ids, "%04x:%04x", settings.vendor_id, settings.product_id);
    *error = !settings.path.empty() ? "no supported HID device at " + settings.path
                                    : std::string("no supported HID device matches ") + ids +
                                          " (0000 is any; proxEnumerateHidDevices lists what is present)";
    return nullptr;
  }
  hid_device* handle = hid_open_path(pick->path.c_str());
  if (!handle) {
    *error = "cannot open " + pick->path + ": " + utf8(hid_error(nullptr)) +
             " (on Linux, read and write access to the hidraw node is needed: a udev rule)";
    return nullptr;
  }
  return std::unique_ptr<HidDevice>(new HidDevice(settings, *pick, handle));
}

HidDevice::HidDevice(const HidDeviceSettings& settings, const HidFound& found, hid_device_* handle)
    : settings_(settings), found_(found), handle_(handle) {
  motion_.reset(settings_.initial_position, settings_.initial_rotation, settings_.reference_local);
  home_ = motion_;
  last_output_ = build_output(found_.profile, 0.0, settings_.output);  // the device starts at rest
  read_calibration();
  if (is_pid(found_.profile)) pid_open();
  connected_.store(true);
  publish(true);
  last_step_ = now_seconds();
  thread_ = std::thread([this] { run(); });
}

HidDevice::~HidDevice() { close(); }

void HidDevice::close() {
  if (closed_.exchange(true, std::memory_order_acq_rel)) return;
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
  pid_stop();  // the effect stopped and freed, the actuators off
  if (handle_) hid_close(handle_);
  handle_ = nullptr;
  connected_.store(false);
}

void HidDevice::read_calibration() {
  const std::uint8_t id = calibration_report_id(found_.profile);
  if (id == 0) return;
  std::uint8_t buf[64] = {id};
  const int n = hid_get_feature_report(handle_, buf, calibration_report_size(found_.profile));
  MotionCalibration c;
  if (n > 0 && parse_calibration(found_.profile, buf, std::size_t(n), c)) calibration_ = c;
}

void HidDevice::publish(bool valid) {
  Published p{};
  motion_.pose(p.pose.position, p.pose.rotation);
  p.valid = valid;
  published_.store(p);
}

void HidDevice::disconnect() {
  if (pid_) {
    pid_->lost();
    effect_state_.store(pid_->state(), std::memory_order_relaxed);
  }
  hid_close(handle_);
  handle_ = nullptr;
  connected_.store(false);
  disconnects_.fetch_add(1, std::memory_order_relaxed);
  // A deflection held when it went must not carry on when it comes back.
  input_ = HidInput{};
  axes_ = HidAxes{};
  recentre_held_ = false;
  if (pid_) motion_ = home_;  // a stick's position is read anew
  publish(false);
}

bool HidDevice::reopen() {
  std::lock_guard<std::mutex> lock(hidapi_mutex());
  for (const HidFound& f : enumerate_locked()) {
    if (f.vendor_id != found_.vendor_id || f.product_id != found_.product_id || f.serial != found_.serial)
      continue;
    hid_device* h = hid_open_path(f.path.c_str());
    if (!h) continue;
    handle_ = h;
    return true;
  }
  return false;
}

void HidDevice::run() {
  std::uint8_t buf[256];
  pid_start(now_seconds());
  while (!stop_.load(std::memory_order_acquire)) {
    if (!handle_) {
      const double now = now_seconds();
      if (now >= next_search_) {
        next_search_ = now + settings_.reconnect_interval;
        if (reopen()) {
          read_calibration();
          last_output_ = build_output(found_.profile, 0.0, settings_.output);
          pid_start(now);  // a reconnected device's effects are gone: created anew
          reconnects_.fetch_add(1, std::memory_order_relaxed);
          connected_.store(true);
          last_step_ = now_seconds();
          publish(true);  // where it was when it went
          continue;
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    // A short timeout: the outputs are written between reads.
    const int n = hid_read_timeout(handle_, buf, sizeof buf, 2);
    const double now = now_seconds();
    if (n < 0) {
      disconnect();
      next_search_ = now + settings_.reconnect_interval;
      continue;
    }
    // The deflection held since the last step moved the tool until now (a
    // rate device; a grounded one is where its last report put it).
    if (!pid_) motion_.step(axes_, settings_.motion, now - last_step_);
    last_step_ = now;
    if (n > 0) {
      const DecodeResult r = pid_ ? pid_input(buf, std::size_t(n))
                                  : decode_hid_report(found_.profile, buf, std::size_t(n), calibration_, input_);
      if (r == DecodeResult::Malformed) {
        malformed_.fetch_add(1, std::memory_order_relaxed);
      } else {
        reports_read_.fetch_add(1, std::memory_order_relaxed);
        last_report_time_.store(now, std::memory_order_relaxed);
        axes_ = hid_axes(found_.profile, input_);
        if (axes_.recentre && !recentre_held_)
          motion_.reset(settings_.initial_position, settings_.initial_rotation, settings_.reference_local);
        recentre_held_ = axes_.recentre;
      }
    }
    publish(true);
    write_outputs(now);
  }
}

void HidDevice::write_outputs(double now) {
  if (pid_) {
    pid_outputs(now);
    return;
  }
  if (now - last_output_time_ < 1.0 / settings_.output_rate) return;
  const runtime::DeviceWrench w = wrench_.load();
  OutputInput in;
  in.force = std::sqrt(w.force[0] * w.force[0] + w.force[1] * w.force[1] + w.force[2] * w.force[2]);
  if (!std::isfinite(in.force)) in.force = 0.0;  // the gate rules it out; never send one anyway
  in.closest_distance = w.closest_distance;      // +inf: none; NaN: not known
  in.safety_distance = w.safety_distance;
  in.cutoff = w.cutoff;
  const OutputReport r = build_output(found_.profile, in, settings_.output);
  if (r.size == 0 || r == last_output_) return;
  last_output_time_ = now;
  if (hid_write(handle_, r.bytes, r.size) == int(r.size)) {
    outputs_written_.fetch_add(1, std::memory_order_relaxed);
    last_output_ = r;
  } else {
    failed_writes_.fetch_add(1, std::memory_order_relaxed);
  }
}

bool HidDevice::read_pose(runtime::DevicePose* pose) {
  pose_reads_.fetch_add(1, std::memory_order_relaxed);
  const Published p = published_.load();
  if (!p.valid || closed_.load(std::memory_order_acquire)) {
    no_pose_ticks_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  *pose = p.pose;
  return true;
}

void HidDevice::write_wrench(const runtime::DeviceWrench& wrench) { wrench_.store(wrench); }

HidStats HidDevice::stats() const {
  HidStats s;
  s.profile = found_.profile;
  s.connected = connected_.load() && !closed();
  s.reports_read = reports_read_.load(std::memory_order_relaxed);
  s.malformed = malformed_.load(std::memory_order_relaxed);
  s.outputs_written = outputs_written_.load(std::memory_order_relaxed);
  s.failed_writes = failed_writes_.load(std::memory_order_relaxed);
  s.disconnects = disconnects_.load(std::memory_order_relaxed);
  s.reconnects = reconnects_.load(std::memory_order_relaxed);
  s.pose_reads = pose_reads_.load(std::memory_order_relaxed);
  s.no_pose_ticks = no_pose_ticks_.load(std::memory_order_relaxed);
  const double t = last_report_time_.load(std::memory_order_relaxed);
  s.last_report_age = t < 0.0 ? -1.0 : now_seconds() - t;
  s.force_updates = force_updates_.load(std::memory_order_relaxed);
  s.effects_created = effects_created_.load(std::memory_order_relaxed);
  s.last_force_magnitude = last_force_magnitude_.load(std::memory_order_relaxed);
  s.max_force_magnitude = max_force_magnitude_.load(std::memory_order_relaxed);
  s.effect = effect_state_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace prox::devices
