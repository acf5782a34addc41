// The viewer's command line (docs/viewer.md): what to load, how the tool is
// driven, what to draw and where.
#pragma once

#include <proxima/proxima.h>

#include <string>

namespace viewer {

// What is drawn; --show picks from these names.
struct Show {
  bool meshes = true, strings = true, polylines = true, force = true, hud = true, grid = true;
  bool ghost = true;  // a constrained tool's device pose, see-through
};

// How the tool is driven. `auto` resolves to one of the others (see resolve()).
enum class DeviceKind { none, scripted, mouse, gamepad, hid };

struct Options {
  std::string mesh_a, mesh_b;  // both empty: the built-in bunny scene (path T)
  proxPose pose_b{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  double cutoff = 0.0;  // 0: the force preset's
  bool headless = false;
  int frames = 0;  // 0: until the window is closed (headless: 1)
  std::string out_dir;
  int width = 1280, height = 720;
  int msaa = 4;  // samples per pixel: 1 or 4
  Show show;
  bool validation = false;
  std::string device = "";  // as given; empty: none with A and B, scripted without
  DeviceKind device_kind = DeviceKind::none;
  std::string poses_file;
  double seconds = 4.0;  // path T: each leg (approach, hold, retreat); --poses: the whole path
  proxMethod method = PROX_METHOD_PRECISE;
  proxForcePreset force = PROX_FORCE_PRESET_HARD;
  proxToolMode tool_mode = PROX_TOOL_FREE;  // constrained: the tool never sinks in (docs/coupling.md)
  // The glTF animation played on A (--animate) and on the tool's mesh B
  // (--animate-b), as proxMesh_GetAnimationInfo numbers them; -1: none.
  int animate_a = -1, animate_b = -1;
  std::string animate_a_option = "--animate";  // as given (--animate or --animate-a), for messages
};

// Thrown for a bad command line; main prints it with the usage and exits 2.
struct UsageError {
  std::string message;
};

extern const char* const kUsage;

// Parses argv; throws UsageError. Sets help when --help was asked for.
Options parse_options(int argc, char** argv, bool* help);

const char* method_name(proxMethod m);
const char* force_name(proxForcePreset f);
const char* device_name(DeviceKind d);

}  // namespace viewer
