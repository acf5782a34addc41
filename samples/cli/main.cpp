// proxima: the command-line face of the engine.
//
//   proxima info FILE
//   proxima lmd A B [--pose-a tx ty tz qw qx qy qz] [--pose-b ...] [--cutoff D]
//                   [--method precise|original|reference] [--force hard|soft]
//                   [--animate-a INDEX:SECONDS] [--animate-b INDEX:SECONDS] [--json FILE]
//   proxima polylines A B [--pose-a ...] [--pose-b ...] [--json FILE]
//   proxima path [A B] [--poses FILE | --steps N] [--method precise|original|both] [--force hard|soft]
//                [--csv FILE]
//
// Poses are world poses of the meshes as loaded (quaternion w first); lengths
// are in the meshes' units (metres for the shared assets). docs/cli.md has
// the details and the JSON layout.
//
//   proxima run [A B] [--device scripted|stream|hid[:VVVV:PPPP]] [--poses FILE] [--seconds S] [--trace
//   FILE.csv] ... proxima devices [--json FILE]
//
// A customer of the SDK like any other: it sees only the C API
// (<proxima/proxima.h>, libproxima.so) and the samples' own utilities.
#include "cli.h"

namespace {

const char* kUsage =
    "usage:\n"
    "  proxima info FILE\n"
    "  proxima lmd A B [--pose-a tx ty tz qw qx qy qz] [--pose-b tx ty tz qw qx qy qz]\n"
    "                  [--cutoff D] [--method precise|original|reference] [--force hard|soft]\n"
    "                  [--patch-radius R] [--patch-angle DEG] [--patch-spread S] [--leaf-budget N]\n"
    "                  [--animate-a INDEX:SECONDS] [--animate-b INDEX:SECONDS] [--json FILE]\n"
    "  proxima polylines A B [--pose-a tx ty tz qw qx qy qz] [--pose-b ...] [--json FILE]\n"
    "  proxima path [A B] [--poses FILE | --steps N] [--method precise|original|both] [--force hard|soft]\n"
    "               [--csv FILE]\n"
    "  proxima run [A B] [--device scripted|stream|hid[:VVVV:PPPP]] [--poses FILE] [--seconds S] [--hold S]\n"
    "              [--method precise|original] [--force hard|soft] [--tool-mode free|constrained]\n"
    "              [--json FILE] [--trace FILE.csv] [--animate-a INDEX] [--animate-b INDEX]\n"
    "              [--stream-rate HZ] [--stream-mode hold|interpolate|extrapolate]\n"
    "              [--haptic-timing auto|spin|sleep] [--spin-margin S] [--realtime] [--lock-memory]\n"
    "  proxima devices [--json FILE]\n"
    "  proxima --version\n";

// The usage of one command: its lines of kUsage (empty: no such command).
std::string usage_of(const std::string& command) {
  const std::string usage = kUsage, start = "  proxima " + command + " ";
  std::size_t from = usage.find(start);
  if (from == std::string::npos) from = usage.find("  proxima " + command + "\n");
  if (from == std::string::npos) return "";
  const std::size_t to = usage.find("  proxima ", from + 1);
  return "usage:\n" + usage.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace proxcli;
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string command = argv[1];
  // `proxima COMMAND --help`: that command's usage, whatever else is given.
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::string usage = usage_of(command);
    if ((arg == "--help" || arg == "-h") && !usage.empty()) {
      std::fputs(usage.c_str(), stdout);
      return 0;
    }
  }
  try {
    Args args(argc, argv, 2);
    if (command == "info") return info(args);
    if (command == "lmd") return lmd(args);
    if (command == "polylines") return polylines(args);
    if (command == "path") return path(args);
    if (command == "run") return run(args);
    if (command == "devices") return devices(args);
    if (command == "--version") {
      std::printf("proxima %s\n", PROX_VERSION_STRING);
      return 0;
    }
    if (command == "--help" || command == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    std::fprintf(stderr, "proxima: unknown command '%s'\n%s", command.c_str(), kUsage);
    return 2;
  } catch (const UserError& e) {
    std::fprintf(stderr, "proxima: %s\n", e.message.c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proxima: %s\n", e.what());
    return 1;
  }
}
