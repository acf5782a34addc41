// The window's input: the mouse orbits and zooms the camera, right-drag
// moves the tool (the mouse device), keys toggle what is shown and switch
// the method and force preset.
#pragma once

#include "camera.h"
#include "options.h"

#include <proxima/proxima.h>

struct GLFWwindow;

namespace viewer {

struct Input {
  Camera* camera = nullptr;
  Show* show = nullptr;
  bool mouse_device = false;
  // Set by the keys; main acts on them and clears them.
  bool switch_method = false, switch_force = false;
  // The tool's drag since the last frame, in world units (mouse device).
  glm::dvec3 tool_drag{0.0};

  double last_x = 0.0, last_y = 0.0;
  bool orbiting = false, dragging = false;
  int window_height = 1;
};

// Installs the callbacks; `input` must outlive the window.
void attach_input(GLFWwindow* window, Input* input);

// The first joystick GLFW knows as a gamepad (it has a mapping), or -1.
// GLFW must be initialised.
int find_gamepad();

// Applies a gamepad's sticks and triggers for `seconds` to a tool pose: the
// left stick moves it in the view plane, the triggers along the view (right
// in, left out), the right stick turns it about the view's up and right
// axes. Full deflection: half the scene's radius and one radian a second;
// a dead zone of 0.15 around rest. False when the gamepad is gone.
bool apply_gamepad(int gamepad, const Camera& camera, double seconds, proxPose* pose);

}  // namespace viewer
