// proxima_hid_emulate: runs a command with emulated HID devices plugged in,
// for the command-line tests (tests/cli/hid_cli_test.py):
//
//   proxima_hid_emulate [--device NAME]... [--send DEVICE SECONDS HEX]...
//                       [--send-after-output DEVICE HEX]... [--record FILE] -- COMMAND...
//
// NAME is one of the shared devices (spacenavigator, spacemouse_wireless,
// ds4v2, dualsense; the force-feedback openffboard, openffboard_1axis and
// arduino_ffb, their effect blocks modelled by emulated_pid.h), plugged in
// as /dev/hidraw0, 1, ... in order. Each
// --send queues an input report (hex bytes, report id first) on device
// DEVICE: the first one at once, each later one SECONDS after the device's
// first report was read (that is, after the command opened it). Each
// --send-after-output queues one once the command has written the device
// its first output report (for a rumble or LED device: the first contact
// felt), closing a test's loop on what the command did, not on time. --record
// writes, as JSON, what each device was written and which feature reports
// were asked for. Exits with the command's status.
#include "hid/emulated_hid.h"
#include "hid/emulated_pid.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

using prox::test::Bytes;

struct Send {
  int device = 0;
  double seconds = 0.0;
  Bytes report;
  bool after_output = false;  // sent once the device was written an output report, not by time
};

Bytes from_hex(const std::string& h) {
  Bytes b;
  for (std::size_t i = 0; i + 1 < h.size(); i += 2)
    b.push_back(std::uint8_t(std::stoul(h.substr(i, 2), nullptr, 16)));
  return b;
}

std::string to_hex(const Bytes& b) {
  std::string s;
  char two[3];
  for (const std::uint8_t v : b) std::snprintf(two, sizeof two, "%02x", v), s += two;
  return s;
}

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "proxima_hid_emulate: %s\nusage: proxima_hid_emulate [--device NAME]... "
               "[--send DEVICE SECONDS HEX]... [--send-after-output DEVICE HEX]... [--record FILE] -- "
               "COMMAND...\n",
               why);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names;
  std::vector<Send> sends;
  std::string record;
  int i = 1;
  for (; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") break;
    if (a == "--device" && i + 1 < argc) {
      names.push_back(argv[++i]);
    } else if (a == "--send" && i + 3 < argc) {
      Send s;
      s.device = std::atoi(argv[++i]);
      s.seconds = std::atof(argv[++i]);
      s.report = from_hex(argv[++i]);
      sends.push_back(s);
    } else if (a == "--send-after-output" && i + 2 < argc) {
      Send s;
      s.device = std::atoi(argv[++i]);
      s.report = from_hex(argv[++i]);
      s.after_output = true;
      sends.push_back(s);
    } else if (a == "--record" && i + 1 < argc) {
      record = argv[++i];
    } else {
      usage(("unknown option " + a).c_str());
    }
  }
  if (i + 1 >= argc) usage("no command after --");
  prox::test::EmulatedHidBus bus(false);
  std::vector<std::shared_ptr<prox::test::EmulatedPid>> models;
  for (const std::string& n : names) {
    prox::test::EmulatedHidSpec spec = prox::test::shared_device(PROX_SHARED_DEVICES_DIR, n);
    if (n == "openffboard" || n == "openffboard_1axis" || n == "arduino_ffb")
      models.push_back(prox::test::EmulatedPid::attach(spec, n == "arduino_ffb" ? 14 : 40));
    bus.add(spec);
  }
  for (const Send& s : sends)
    if (s.device < 0 || s.device >= int(names.size())) usage("--send names a device not plugged in");

  // The child's environment: ours, with the bus and the preload (ASan must
  // not insist on coming first then).
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "LD_PRELOAD=", 11) != 0 && std::strncmp(*e, "UMOCKDEV_DIR=", 13) != 0 &&
        std::strncmp(*e, "ASAN_OPTIONS=", 13) != 0)
      env.push_back(*e);
  // Preloads already asked for (a sanitizer's runtime) stay first.
  const char* preload = std::getenv("LD_PRELOAD");
  for (const std::string& e : bus.child_environment())
    env.push_back(e.rfind("LD_PRELOAD=", 0) == 0 && preload && *preload
                      ? "LD_PRELOAD=" + std::string(preload) + " " + e.substr(11)
                      : e);
  const char* asan = std::getenv("ASAN_OPTIONS");
  env.push_back(std::string("ASAN_OPTIONS=verify_asan_link_order=0") + (asan ? std::string(":") + asan : ""));
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);

  // The first report of each device at once; it is read when the command
  // opens it. `done` says which sends are behind us.
  std::vector<bool> first_sent(names.size(), false), done(sends.size(), false);
  for (std::size_t k = 0; k < sends.size(); ++k) {
    const Send& s = sends[k];
    if (!s.after_output && !first_sent[std::size_t(s.device)])
      bus.send(s.device, s.report), first_sent[std::size_t(s.device)] = true, done[k] = true;
  }

  const pid_t child = fork();
  if (child == 0) {
    execvpe(argv[i + 1], argv + i + 1, envp.data());
    std::perror("proxima_hid_emulate: exec");
    _exit(127);
  }
  // The later reports, timed from when each device's first was read.
  std::thread feeder([&] {
    std::vector<double> opened(names.size(), -1.0);
    const auto now = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
    for (;;) {
      bool left = false;
      for (std::size_t k = 0; k < sends.size(); ++k) {
        if (done[k]) continue;
        left = true;
        const std::size_t d = std::size_t(sends[k].device);
        if (sends[k].after_output) {
          if (!bus.writes(int(d)).empty()) bus.send(int(d), sends[k].report), done[k] = true;
          continue;
        }
        if (opened[d] < 0.0 && bus.pending(int(d)) == 0) opened[d] = now();
        if (opened[d] >= 0.0 && now() >= opened[d] + sends[k].seconds)
          bus.send(int(d), sends[k].report), done[k] = true;
      }
      int status = 0;
      if (!left || waitpid(child, &status, WNOHANG) != 0) {
        if (left)
          std::fprintf(stderr, "proxima_hid_emulate: the command ended before every report was sent\n");
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  int status = 0;
  feeder.join();
  waitpid(child, &status, 0);
  if (!record.empty()) {
    std::ofstream f(record);
    f << "{\"devices\": [";
    for (std::size_t d = 0; d < names.size(); ++d) {
      f << (d ? ", " : "") << "{\"name\": \"" << names[d] << "\", \"node\": \"" << bus.node(int(d))
        << "\", \"writes\": [";
      const std::vector<Bytes> w = bus.writes(int(d));
      for (std::size_t k = 0; k < w.size(); ++k) f << (k ? ", " : "") << '"' << to_hex(w[k]) << '"';
      f << "], \"feature_requests\": [";
      const std::vector<std::uint8_t> fr = bus.feature_requests(int(d));
      for (std::size_t k = 0; k < fr.size(); ++k) f << (k ? ", " : "") << int(fr[k]);
      f << "], \"pending\": " << bus.pending(int(d)) << "}";
    }
    f << "]}\n";
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}
