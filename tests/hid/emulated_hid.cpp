#include "hid/emulated_hid.h"

#include <gtest/gtest.h>
#include <umockdev.h>

#include <linux/hidraw.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>

namespace prox::test {
namespace {

std::string hex(const Bytes& b) {
  std::string s;
  char two[3];
  for (const std::uint8_t v : b) {
    std::snprintf(two, sizeof two, "%02x", v);
    s += two;
  }
  return s;
}

std::string x4(unsigned v, bool upper) {
  char s[8];
  std::snprintf(s, sizeof s, upper ? "%04X" : "%04x", v);
  return s;
}

Bytes read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// Little-endian int16 into a reply.
void put16(Bytes& b, std::size_t at, int v) {
  b[at] = std::uint8_t(v & 0xff);
  b[at + 1] = std::uint8_t((v >> 8) & 0xff);
}

}  // namespace

EmulatedHidSpec shared_device(const std::string& dir, const std::string& name) {
  EmulatedHidSpec s;
  std::string file;
  if (name == "spacenavigator") {
    s.vendor_id = 0x046d, s.product_id = 0xc626, s.interface_number = 0, s.bcd_device = 0x0435;
    s.manufacturer = "3Dconnexion", s.product = "SpaceNavigator";
    file = "spacenavigator_046d_c626_228b";
  } else if (name == "spacemouse_wireless") {
    s.vendor_id = 0x256f, s.product_id = 0xc62e, s.interface_number = 0, s.bcd_device = 0x0441;
    s.manufacturer = "3Dconnexion", s.product = "SpaceMouse Wireless";
    file = "spacemouse_wireless_256f_c62e";
  } else if (name == "ds4v2" || name == "dualsense") {
    const bool ds4 = name == "ds4v2";
    s.vendor_id = 0x054c, s.product_id = ds4 ? 0x09cc : 0x0ce6, s.interface_number = 3;
    s.manufacturer = "Sony Interactive Entertainment", s.product = "Wireless Controller";
    file = ds4 ? "ds4v2_054c_09cc" : "dualsense_054c_0ce6";
    // Motion calibration (DS4 0x02, 37 bytes; DualSense 0x05, 41 bytes), USB
    // word order: gyro bias p/y/r, pitch +/-, yaw +/-, roll +/-, speed +/-,
    // accel x +/-, y +/-, z +/-.
    Bytes cal(ds4 ? 37 : 41, 0);
    cal[0] = ds4 ? 0x02 : 0x05;
    const int words[] = {4,   -3,  2,    8000,  -8000, 8100,  -8100, 7900, -7900,
                         540, 540, 8200, -8100, 8300,  -8000, 8150,  -8250};
    for (int i = 0; i < 17; ++i) put16(cal, std::size_t(1 + 2 * i), words[i]);
    s.features[cal[0]] = cal;
  } else if (name == "openffboard" || name == "openffboard_1axis") {
    s.vendor_id = 0x1209, s.product_id = 0xffb0, s.interface_number = 0, s.bcd_device = 0x0100;
    s.manufacturer = "Open FFBoard", s.product = "FFBoard";
    file = name == "openffboard" ? "pid/openffboard_1209_ffb0" : "pid/openffboard_1209_ffb0_1axis";
  } else if (name == "arduino_ffb") {
    s.vendor_id = 0x2341, s.product_id = 0x8036, s.interface_number = 2, s.bcd_device = 0x0100;
    s.manufacturer = "Arduino LLC", s.product = "Arduino Leonardo";
    file = "pid/arduino_joystick_ffb_2341_8036";
  } else {
    ADD_FAILURE() << "no shared device named " << name;
    return s;
  }
  s.descriptor = read_file(dir + "/" + file + ".rdesc.bin");
  if (s.descriptor.empty()) ADD_FAILURE() << "missing " << dir << "/" << file << ".rdesc.bin";
  s.serial = "emulated-" + x4(s.product_id, false);
  return s;
}

struct EmulatedHidBus::Device {
  EmulatedHidSpec spec;
  int index = 0;   // the test's name for it
  int number = 0;  // hidrawN: a new one at each replug, as on a real bus
  std::string node, hidraw_syspath;
  UMockdevIoctlBase* handler = nullptr;
  Impl* bus = nullptr;
  // Under Impl::mutex:
  std::deque<Bytes> queue;
  bool in_flight = false;  // a report sits in the PTY, not read yet
  bool plugged = false;
  std::vector<Bytes> writes, features_sent;
  std::vector<double> write_times;
  std::vector<std::uint8_t> feature_requests;
  double write_delay = 0.0;
};

struct EmulatedHidBus::Impl {
  UMockdevTestbed* testbed = nullptr;
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::unique_ptr<Device>> devices;
  std::vector<std::thread> late;  // delayed write completions
  int next_number = 0;

  // Under mutex: puts the next queued report into the PTY once the last was read.
  void feed(Device& d) {
    if (d.in_flight || d.queue.empty() || !d.plugged) return;
    const int fd = umockdev_testbed_get_dev_fd(testbed, d.node.c_str());
    const Bytes r = d.queue.front();
    d.queue.pop_front();
    if (fd >= 0 && ::write(fd, r.data(), r.size()) == ssize_t(r.size())) d.in_flight = true;
    changed.notify_all();
  }

  static gboolean on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user);
  static gboolean on_read(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user);
  static gboolean on_write(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user);
  void attach(Device& d);

  // The device's sysfs paths: hidraw node, hid device, USB interface, USB device.
  std::vector<std::string> syspaths(const Device& d) const {
    const EmulatedHidSpec& s = d.spec;
    const std::string usb = "/devices/pci0000:00/0000:00:14.0/usb1/1-" + std::to_string(d.number + 1);
    const std::string intf =
        usb + "/1-" + std::to_string(d.number + 1) + ":1." + std::to_string(s.interface_number);
    const std::string hid = intf + "/" + hid_name(d);
    return {hid + "/hidraw/hidraw" + std::to_string(d.number), hid, intf, usb};
  }
  static std::string hid_name(const Device& d) {
    return "0003:" + x4(d.spec.vendor_id, true) + ":" + x4(d.spec.product_id, true) + "." +
           x4(unsigned(d.number + 1), true);
  }

  std::string description(const Device& d) const {
    const EmulatedHidSpec& s = d.spec;
    const std::vector<std::string> p = syspaths(d);
    const std::string &hid = p[1], &intf = p[2], &usb = p[3];
    const std::string hid_name = EmulatedHidBus::Impl::hid_name(d);
    const std::string raw = "hidraw" + std::to_string(d.number);
    std::string t;
    t += "P: " + p[0] + "\nN: " + raw + "\nE: DEVNAME=/dev/" + raw +
         "\nE: SUBSYSTEM=hidraw\nE: MAJOR=240\nE: MINOR=" + std::to_string(d.number) +
         "\nA: dev=240:" + std::to_string(d.number) + "\nL: device=../../../" + hid_name + "\n\n";
    t += "P: " + hid + "\nE: DRIVER=hid-generic\nE: HID_ID=0003:0000" + x4(s.vendor_id, true) + ":0000" +
         x4(s.product_id, true) + "\nE: HID_NAME=" + s.manufacturer + " " + s.product +
         "\nE: HID_UNIQ=" + s.serial + "\nE: SUBSYSTEM=hid\nH: report_descriptor=" + hex(s.descriptor) +
         "\n\n";
    t += "P: " + intf + "\nE: DEVTYPE=usb_interface\nE: SUBSYSTEM=usb\nA: bInterfaceNumber=" +
         (s.interface_number < 10 ? "0" : "") + std::to_string(s.interface_number) +
         "\nA: bInterfaceClass=03\n\n";
    t += "P: " + usb + "\nE: DEVTYPE=usb_device\nE: SUBSYSTEM=usb\nA: idVendor=" + x4(s.vendor_id, false) +
         "\nA: idProduct=" + x4(s.product_id, false) + "\nA: bcdDevice=" + x4(s.bcd_device, false) +
         "\nA: manufacturer=" + s.manufacturer + "\nA: product=" + s.product + "\nA: serial=" + s.serial +
         "\nA: busnum=1\nA: devnum=" + std::to_string(d.number + 2) + "\n\n";
    return t;
  }
};

}  // namespace prox::test

namespace prox::test {
namespace {

// Copies `n` bytes into the client's buffer that `arg` points to.
bool fill(UMockdevIoctlData* arg, std::size_t size, const void* bytes, std::size_t n) {
  GError* error = nullptr;
  UMockdevIoctlData* data = umockdev_ioctl_data_resolve(arg, 0, size, &error);
  if (!data) {
    if (error) g_error_free(error);
    return false;
  }
  std::memcpy(data->data, bytes, std::min<std::size_t>(n, std::size_t(data->data_len)));
  umockdev_ioctl_data_unref(data);
  return true;
}

// The client's buffer that `arg` points to, as bytes.
Bytes fetch(UMockdevIoctlData* arg, std::size_t size) {
  GError* error = nullptr;
  UMockdevIoctlData* data = umockdev_ioctl_data_resolve(arg, 0, size, &error);
  if (!data) {
    if (error) g_error_free(error);
    return {};
  }
  Bytes b(data->data, data->data + data->data_len);
  umockdev_ioctl_data_unref(data);
  return b;
}

}  // namespace

gboolean EmulatedHidBus::Impl::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user) {
  Device& d = *static_cast<Device*>(user);
  const unsigned long request = umockdev_ioctl_client_get_request(client);
  if (_IOC_TYPE(request) != 'H') return FALSE;
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const std::size_t size = _IOC_SIZE(request);
  std::unique_lock<std::mutex> lock(d.bus->mutex);
  if (!d.plugged) {
    umockdev_ioctl_client_complete(client, -1, ENODEV);
    return TRUE;
  }
  const EmulatedHidSpec& s = d.spec;
  switch (_IOC_NR(request)) {
    case 0x01: {  // HIDIOCGRDESCSIZE
      const int n = int(s.descriptor.size());
      umockdev_ioctl_client_complete(client, fill(arg, sizeof n, &n, sizeof n) ? 0 : -1, EFAULT);
      return TRUE;
    }
    case 0x02: {  // HIDIOCGRDESC
      hidraw_report_descriptor desc{};
      desc.size = std::uint32_t(s.descriptor.size());
      std::memcpy(desc.value, s.descriptor.data(), s.descriptor.size());
      umockdev_ioctl_client_complete(client, fill(arg, sizeof desc, &desc, sizeof desc) ? 0 : -1, EFAULT);
      return TRUE;
    }
    case 0x03: {  // HIDIOCGRAWINFO
      hidraw_devinfo info{};
      info.bustype = 3;
      info.vendor = std::int16_t(s.vendor_id);
      info.product = std::int16_t(s.product_id);
      umockdev_ioctl_client_complete(client, fill(arg, sizeof info, &info, sizeof info) ? 0 : -1, EFAULT);
      return TRUE;
    }
    case 0x04:    // HIDIOCGRAWNAME
    case 0x05:    // HIDIOCGRAWPHYS
    case 0x08: {  // HIDIOCGRAWUNIQ
      const std::string text = _IOC_NR(request) == 0x04 ? s.manufacturer + " " + s.product
                               : _IOC_NR(request) == 0x05
                                   ? "usb-emulated/input" + std::to_string(s.interface_number)
                                   : s.serial;
      const std::size_t n = std::min(text.size() + 1, size);
      umockdev_ioctl_client_complete(client, fill(arg, size, text.c_str(), n) ? long(n) : -1, EFAULT);
      return TRUE;
    }
    case 0x06: {  // HIDIOCSFEATURE
      d.features_sent.push_back(fetch(arg, size));
      if (s.on_set_feature) s.on_set_feature(d.features_sent.back());
      umockdev_ioctl_client_complete(client, long(size), 0);
      return TRUE;
    }
    case 0x07: {  // HIDIOCGFEATURE: byte 0 names the report
      Bytes asked = fetch(arg, size);
      if (asked.empty()) {
        umockdev_ioctl_client_complete(client, -1, EFAULT);
        return TRUE;
      }
      d.feature_requests.push_back(asked[0]);
      Bytes reply;
      if (s.on_get_feature && s.on_get_feature(asked[0], reply)) {
        const std::size_t n = std::min(reply.size(), size);
        umockdev_ioctl_client_complete(client, fill(arg, size, reply.data(), n) ? long(n) : -1, EFAULT);
        return TRUE;
      }
      const auto it = s.features.find(asked[0]);
      if (it == s.features.end()) {
        umockdev_ioctl_client_complete(client, -1,
                                       EPIPE);  // what hidraw says for a report the device refuses
        return TRUE;
      }
      const std::size_t n = std::min(it->second.size(), size);
      umockdev_ioctl_client_complete(client, fill(arg, size, it->second.data(), n) ? long(n) : -1, EFAULT);
      return TRUE;
    }
    default:
      umockdev_ioctl_client_complete(client, -1, EINVAL);
      return TRUE;
  }
}

gboolean EmulatedHidBus::Impl::on_read(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user) {
  Device& d = *static_cast<Device*>(user);
  {
    std::lock_guard<std::mutex> lock(d.bus->mutex);
    if (!d.plugged) {
      umockdev_ioctl_client_complete(client, -1, ENODEV);
      return TRUE;
    }
  }
  // The real read, of the PTY the report was put into.
  int err = 0;
  GError* error = nullptr;
  const int n = umockdev_ioctl_client_execute(client, &err, &error);
  if (error) g_error_free(error);
  umockdev_ioctl_client_complete(client, n, err);
  std::lock_guard<std::mutex> lock(d.bus->mutex);
  if (n > 0) {
    d.in_flight = false;
    d.bus->feed(d);
    d.bus->changed.notify_all();
  }
  return TRUE;
}

gboolean EmulatedHidBus::Impl::on_write(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user) {
  Device& d = *static_cast<Device*>(user);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  std::lock_guard<std::mutex> lock(d.bus->mutex);
  if (!d.plugged) {
    umockdev_ioctl_client_complete(client, -1, ENODEV);
    return TRUE;
  }
  d.writes.emplace_back(arg->data, arg->data + arg->data_len);
  if (d.spec.on_output) d.spec.on_output(d.writes.back());
  d.write_times.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count());
  const long n = arg->data_len;
  if (d.write_delay > 0.0) {
    // Answered later, from another thread (complete() is thread-safe): the
    // worker thread keeps serving the other devices meanwhile.
    g_object_ref(client);
    const double delay = d.write_delay;
    d.bus->late.emplace_back([client, n, delay] {
      std::this_thread::sleep_for(std::chrono::duration<double>(delay));
      umockdev_ioctl_client_complete(client, n, 0);
      g_object_unref(client);
    });
    return TRUE;
  }
  umockdev_ioctl_client_complete(client, n, 0);
  d.bus->changed.notify_all();
  return TRUE;
}

void EmulatedHidBus::Impl::attach(Device& d) {
  GError* error = nullptr;
  if (!umockdev_testbed_add_from_string(testbed, description(d).c_str(), &error)) {
    ADD_FAILURE() << "umockdev could not add " << d.node << ": " << (error ? error->message : "?");
    if (error) g_error_free(error);
    return;
  }
  d.handler = umockdev_ioctl_base_new();
  g_signal_connect(d.handler, "handle-ioctl", G_CALLBACK(on_ioctl), &d);
  g_signal_connect(d.handler, "handle-read", G_CALLBACK(on_read), &d);
  g_signal_connect(d.handler, "handle-write", G_CALLBACK(on_write), &d);
  if (!umockdev_testbed_attach_ioctl(testbed, d.node.c_str(), d.handler, &error)) {
    ADD_FAILURE() << "umockdev could not attach to " << d.node << ": " << (error ? error->message : "?");
    if (error) g_error_free(error);
  }
}

EmulatedHidBus::EmulatedHidBus(bool in_process) : impl_(std::make_unique<Impl>()) {
  impl_->testbed = umockdev_testbed_new();
  if (in_process && !umockdev_in_mock_environment())
    ADD_FAILURE() << "not under umockdev's preload: run the test through umockdev-wrapper";
}

EmulatedHidBus::~EmulatedHidBus() {
  // No handler runs once detached; then the delayed completions end.
  std::vector<std::string> nodes;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    for (auto& d : impl_->devices)
      if (d->plugged) nodes.push_back(d->node);
  }
  for (const std::string& n : nodes) umockdev_testbed_detach_ioctl(impl_->testbed, n.c_str(), nullptr);
  for (;;) {
    std::vector<std::thread> late;
    {
      std::lock_guard<std::mutex> lock(impl_->mutex);
      late.swap(impl_->late);
    }
    if (late.empty()) break;
    for (std::thread& t : late) t.join();
  }
  for (auto& d : impl_->devices)
    if (d->handler) g_object_unref(d->handler);
  g_object_unref(impl_->testbed);
}

int EmulatedHidBus::add(const EmulatedHidSpec& spec) {
  auto d = std::make_unique<Device>();
  d->spec = spec;
  d->bus = impl_.get();
  Device& ref = *d;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    d->index = int(impl_->devices.size());
    d->number = impl_->next_number++;
    d->node = "/dev/hidraw" + std::to_string(d->number);
    impl_->devices.push_back(std::move(d));
  }
  impl_->attach(ref);
  std::lock_guard<std::mutex> lock(impl_->mutex);
  ref.plugged = true;
  return ref.index;
}

std::string EmulatedHidBus::node(int device) const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->devices.at(std::size_t(device))->node;
}

void EmulatedHidBus::send(int device, const Bytes& report) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  Device& d = *impl_->devices.at(std::size_t(device));
  d.queue.push_back(report);
  impl_->feed(d);
}

std::size_t EmulatedHidBus::pending(int device) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const Device& d = *impl_->devices.at(std::size_t(device));
  return d.queue.size() + (d.in_flight ? 1 : 0);
}

bool EmulatedHidBus::drain(int device, double seconds) {
  std::unique_lock<std::mutex> lock(impl_->mutex);
  const Device& d = *impl_->devices.at(std::size_t(device));
  return impl_->changed.wait_for(lock, std::chrono::duration<double>(seconds),
                                 [&] { return d.queue.empty() && !d.in_flight; });
}

std::vector<Bytes> EmulatedHidBus::writes(int device) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->devices.at(std::size_t(device))->writes;
}

std::vector<double> EmulatedHidBus::write_times(int device) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->devices.at(std::size_t(device))->write_times;
}

std::vector<std::uint8_t> EmulatedHidBus::feature_requests(int device) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->devices.at(std::size_t(device))->feature_requests;
}

std::vector<Bytes> EmulatedHidBus::features_sent(int device) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->devices.at(std::size_t(device))->features_sent;
}

void EmulatedHidBus::set_write_delay(int device, double seconds) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->devices.at(std::size_t(device))->write_delay = seconds;
}

void EmulatedHidBus::unplug(int device) {
  Device* d = nullptr;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    d = impl_->devices.at(std::size_t(device)).get();
    if (!d->plugged) return;
    d->plugged = false;
    d->queue.clear();
    // A byte in the PTY wakes a reader's poll(); its read then fails.
    const int fd = umockdev_testbed_get_dev_fd(impl_->testbed, d->node.c_str());
    const std::uint8_t wake = 0;
    if (fd >= 0 && !d->in_flight && ::write(fd, &wake, 1) != 1) ADD_FAILURE() << "could not wake " << d->node;
    d->in_flight = false;
  }
  // Gone from sysfs, node first (each leaves its class link behind
  // otherwise): enumeration no longer finds it.
  for (const std::string& path : impl_->syspaths(*d))
    umockdev_testbed_remove_device(impl_->testbed, ("/sys" + path).c_str());
}

void EmulatedHidBus::replug(int device) {
  Device* d = nullptr;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    d = impl_->devices.at(std::size_t(device)).get();
    if (d->plugged) return;
  }
  umockdev_testbed_detach_ioctl(impl_->testbed, d->node.c_str(), nullptr);
  if (d->handler) g_object_unref(d->handler);
  d->handler = nullptr;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    d->number = impl_->next_number++;
    d->node = "/dev/hidraw" + std::to_string(d->number);
  }
  impl_->attach(*d);
  std::lock_guard<std::mutex> lock(impl_->mutex);
  d->plugged = true;
}

bool EmulatedHidBus::plugged(int device) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->devices.at(std::size_t(device))->plugged;
}

std::vector<std::string> EmulatedHidBus::child_environment() const {
  return {"UMOCKDEV_DIR=" + root_dir(), "LD_PRELOAD=libumockdev-preload.so.0"};
}

std::string EmulatedHidBus::root_dir() const {
  gchar* dir = umockdev_testbed_get_root_dir(impl_->testbed);
  std::string s = dir ? dir : "";
  g_free(dir);
  return s;
}

}  // namespace prox::test
