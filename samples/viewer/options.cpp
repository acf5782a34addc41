#include "options.h"

#include "hid_input.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace viewer {

const char* const kUsage =
    "usage: proxima-viewer [A B] [options]\n"
    "\n"
    "Draws two meshes, the LMD strings between them, the intersection polylines\n"
    "and the force on the held tool, in a window or headless (offscreen).\n"
    "No meshes: the built-in scene, the Stanford bunny held and moved towards\n"
    "another along path T (as `proxima path`). With A and B: A static at the\n"
    "origin, B the held tool at --pose-b.\n"
    "\n"
    "  --pose-b tx ty tz qw qx qy qz   world pose of B (default identity)\n"
    "  --cutoff D                      contacts farther apart are not wanted (m; default: the force "
    "preset's)\n"
    "  --method precise|original       the improved method or the Johnson-Cohen baseline (default precise)\n"
    "  --force hard|soft               force settings (docs/cli.md; default hard)\n"
    "  --tool-mode free|constrained    constrained: the tool (a proxy) stops at the safety distance while\n"
    "                                  the device goes on, drawn as a see-through ghost (docs/coupling.md)\n"
    "  --device auto|scripted|mouse|gamepad|hid  what drives the tool:\n"
    "                                    scripted: the scripted device along path T (approach, hold,\n"
    "                                    retreat, looped) or along --poses\n"
    "                                    mouse: right-drag moves the tool in the view plane\n"
    "                                    gamepad: the left stick moves it in the view plane, the\n"
    "                                    triggers along the view, the right stick turns it\n"
    "                                    (mouse and gamepad through the streamed device; window only)\n"
    "                                    hid: a SpaceMouse, DualShock 4 or DualSense through hidapi\n"
    "                                    (docs/devices.md; also headless)\n"
    "                                    auto: a HID device if one is plugged in, else in a window a\n"
    "                                    gamepad if one is connected, else the mouse; headless scripted\n"
    "                                  default: scripted without meshes; with A and B the tool stays put\n"
    "  --animate INDEX                 play A's glTF animation INDEX (as `proxima info` numbers them),\n"
    "                                  looped over its keyframes: real time in a window, frame / 60 s\n"
    "                                  headless; the mesh is posed with proxMesh_Animate and drawn as\n"
    "                                  the world holds it (also --animate-a)\n"
    "  --animate-b INDEX               the same for the tool's mesh B\n"
    "  --poses FILE                    the scripted device's path: one pose per line, tx ty tz qw qx qy qz\n"
    "  --seconds S                     path T: the time of each leg; --poses: of the whole path (default 4)\n"
    "  --headless                      render offscreen (no display needed; picks the CPU Vulkan device)\n"
    "  --frames N                      render N frames, then exit (headless default 1; window: until "
    "closed)\n"
    "  --out DIR                       write DIR/frame-0000.png and frame-0000.json per frame (headless)\n"
    "  --size WxH                      image or window size in pixels (default 1280x720)\n"
    "  --msaa 1|4                      samples per pixel (default 4)\n"
    "  --show LIST                     comma-separated: meshes,strings,polylines,force,hud,grid,ghost, all "
    "or\n"
    "                                  none (default all)\n"
    "  --validation                    Vulkan validation layers on; any message is printed and makes\n"
    "                                  the exit status non-zero\n"
    "  --help\n"
    "\n"
    "In a window: left-drag orbits, the wheel zooms, right-drag moves the tool (--device mouse),\n"
    "1-6 toggle meshes, strings, polylines, force, HUD and grid, M switches the method, F the\n"
    "force preset, Esc quits.\n";

namespace {

[[noreturn]] void fail(const std::string& message) { throw UsageError{message}; }

double number(const std::string& text, const std::string& what) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    fail(what + ": '" + text + "' is not a finite number");
  return v;
}

int integer(const std::string& text, const std::string& what, int lo, int hi) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
    fail(what + ": '" + text + "' is not an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
         "]");
  return static_cast<int>(v);
}

Show parse_show(const std::string& list) {
  Show s{false, false, false, false, false, false, false};
  if (list == "all") return Show{};
  if (list == "none" || list.empty()) return s;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item == "meshes")
      s.meshes = true;
    else if (item == "strings")
      s.strings = true;
    else if (item == "polylines")
      s.polylines = true;
    else if (item == "force")
      s.force = true;
    else if (item == "hud")
      s.hud = true;
    else if (item == "grid")
      s.grid = true;
    else if (item == "ghost")
      s.ghost = true;
    else
      fail("--show: '" + item + "' is not one of meshes, strings, polylines, force, hud, grid, ghost");
  }
  return s;
}

}  // namespace

Options parse_options(int argc, char** argv, bool* help) {
  Options o;
  *help = false;
  std::vector<std::string> args(argv + 1, argv + argc);
  std::vector<std::string> meshes;
  std::size_t i = 0;
  auto next = [&](const std::string& what) -> std::string {
    if (i >= args.size()) fail("missing " + what);
    return args[i++];
  };
  bool frames_given = false;
  while (i < args.size()) {
    const std::string a = args[i++];
    if (a == "--help" || a == "-h") {
      *help = true;
      return o;
    } else if (a == "--pose-b") {
      double v[7];
      for (double& x : v) x = number(next("--pose-b value"), "--pose-b");
      if (v[3] == 0.0 && v[4] == 0.0 && v[5] == 0.0 && v[6] == 0.0)
        fail("--pose-b: the quaternion (qw qx qy qz) is zero");
      o.pose_b = {{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}};
    } else if (a == "--cutoff") {
      o.cutoff = number(next("--cutoff value"), "--cutoff");
      if (!(o.cutoff > 0.0)) fail("--cutoff must be positive");
    } else if (a == "--headless") {
      o.headless = true;
    } else if (a == "--frames") {
      o.frames = integer(next("--frames value"), "--frames", 1, 1000000);
      frames_given = true;
    } else if (a == "--out") {
      o.out_dir = next("--out directory");
    } else if (a == "--size") {
      const std::string s = next("--size value");
      const auto x = s.find('x');
      if (x == std::string::npos) fail("--size: '" + s + "' is not WxH");
      o.width = integer(s.substr(0, x), "--size width", 16, 8192);
      o.height = integer(s.substr(x + 1), "--size height", 16, 8192);
    } else if (a == "--msaa") {
      o.msaa = integer(next("--msaa value"), "--msaa", 1, 4);
      if (o.msaa != 1 && o.msaa != 4) fail("--msaa: " + std::to_string(o.msaa) + " is not 1 or 4");
    } else if (a == "--show") {
      o.show = parse_show(next("--show list"));
    } else if (a == "--validation") {
      o.validation = true;
    } else if (a == "--device") {
      o.device = next("--device value");
      if (o.device == "hid" && !hid_supported())
        fail("--device hid: this libproxima was built without HID devices (PROX_WITH_HIDAPI)");
      if (o.device != "auto" && o.device != "scripted" && o.device != "mouse" && o.device != "gamepad" &&
          o.device != "hid")
        fail("--device: '" + o.device + "' is not auto, scripted, mouse, gamepad or hid");
    } else if (a == "--animate" || a == "--animate-a" || a == "--animate-b") {
      const int index = integer(next(a + " index"), a, 0, 2147483647);
      if (a == "--animate-b") {
        o.animate_b = index;
      } else {
        o.animate_a = index;
        o.animate_a_option = a;
      }
    } else if (a == "--poses") {
      o.poses_file = next("--poses file");
    } else if (a == "--seconds") {
      o.seconds = number(next("--seconds value"), "--seconds");
      if (!(o.seconds > 0.0 && o.seconds <= 3600.0)) fail("--seconds must be in (0, 3600]");
    } else if (a == "--method") {
      const std::string m = next("--method value");
      if (m == "precise")
        o.method = PROX_METHOD_PRECISE;
      else if (m == "original")
        o.method = PROX_METHOD_ORIGINAL;
      else
        fail("--method: '" + m + "' is not precise or original");
    } else if (a == "--force") {
      const std::string f = next("--force value");
      if (f == "hard")
        o.force = PROX_FORCE_PRESET_HARD;
      else if (f == "soft")
        o.force = PROX_FORCE_PRESET_SOFT;
      else
        fail("--force: '" + f + "' is not hard or soft");
    } else if (a == "--tool-mode") {
      const std::string m = next("--tool-mode value");
      if (m == "free")
        o.tool_mode = PROX_TOOL_FREE;
      else if (m == "constrained")
        o.tool_mode = PROX_TOOL_CONSTRAINED;
      else
        fail("--tool-mode: '" + m + "' is not free or constrained");
    } else if (!a.empty() && a[0] == '-') {
      fail("unknown option '" + a + "'");
    } else {
      meshes.push_back(a);
    }
  }
  if (meshes.size() == 1 || meshes.size() > 2) fail("give two meshes (A B) or none");
  if (meshes.size() == 2) {
    o.mesh_a = meshes[0];
    o.mesh_b = meshes[1];
  }
  if (o.headless && !frames_given) o.frames = 1;
  if (!o.out_dir.empty() && !o.headless) fail("--out writes headless frames: add --headless");
  if (o.device.empty()) {
    o.device_kind = o.mesh_a.empty() || !o.poses_file.empty() ? DeviceKind::scripted : DeviceKind::none;
  } else if (o.device == "auto" && hid_present()) {
    o.device_kind = DeviceKind::hid;  // hid > gamepad > mouse > scripted
  } else if (o.device == "auto") {
    // In a window the viewer looks for a gamepad once GLFW is up (main.cpp).
    o.device_kind = o.headless ? DeviceKind::scripted : DeviceKind::mouse;
  } else if (o.device == "hid") {
    o.device_kind = DeviceKind::hid;
  } else if (o.device == "scripted") {
    o.device_kind = DeviceKind::scripted;
  } else {
    if (o.headless) fail("--device " + o.device + " needs a window (drop --headless)");
    o.device_kind = o.device == "mouse" ? DeviceKind::mouse : DeviceKind::gamepad;
  }
  if (!o.poses_file.empty() && o.device_kind != DeviceKind::scripted)
    fail("--poses is the scripted device's path: it needs --device scripted");
  return o;
}

const char* method_name(proxMethod m) { return m == PROX_METHOD_ORIGINAL ? "original" : "precise"; }
const char* force_name(proxForcePreset f) { return f == PROX_FORCE_PRESET_SOFT ? "soft" : "hard"; }
const char* device_name(DeviceKind d) {
  switch (d) {
    case DeviceKind::scripted:
      return "scripted";
    case DeviceKind::mouse:
      return "mouse";
    case DeviceKind::gamepad:
      return "gamepad";
    case DeviceKind::hid:
      return "hid";
    default:
      return "none";
  }
}

}  // namespace viewer
