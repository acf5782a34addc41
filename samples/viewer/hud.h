// The HUD's figures, and the text-free HUD: a panel of bars in the
// top-left corner drawn by the lines pipeline in pixels, for builds without
// ImGui (hud_text.h draws them as text; docs/viewer.md says how to read the
// bars).
#pragma once

#include "draw_list.h"

namespace viewer {

struct HudState {
  double frame_seconds = 0.0;                // the last frame's, CPU and GPU
  const proxThreadStats* threads = nullptr;  // haptic, local, global; nullptr: the world was stepped
  bool stepped_each_frame = false;           // stepped, once per frame (an animated mesh), not once
  std::size_t contacts = 0;
  double force = 0.0, max_force = 1.0;  // N
  double torque = 0.0;                  // N m
  proxMethod method = PROX_METHOD_PRECISE;
  proxForcePreset preset = PROX_FORCE_PRESET_HARD;
  DeviceKind device = DeviceKind::none;
};

// Bars from the top, each a track with its fill: frame time (full at 50 ms;
// green under 16.7 ms, yellow under 33.3 ms, red above), the haptic, local
// and global threads' achieved rate (full at the target; global full at
// 100 Hz), the LMD count (log scale, full at 1000), |force| (full at the
// maximum). Then two squares: the method (blue precise, orange original)
// and the device (grey none, violet scripted, teal mouse, yellow gamepad).
void add_hud(DrawList& list, const HudState& hud);

}  // namespace viewer
