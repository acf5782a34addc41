#include "input.h"

#include <GLFW/glfw3.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace viewer {

namespace {

Input* of(GLFWwindow* w) { return static_cast<Input*>(glfwGetWindowUserPointer(w)); }

void on_button(GLFWwindow* w, int button, int action, int) {
  Input* in = of(w);
  glfwGetCursorPos(w, &in->last_x, &in->last_y);
  if (button == GLFW_MOUSE_BUTTON_LEFT) in->orbiting = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) in->dragging = action == GLFW_PRESS && in->mouse_device;
}

void on_cursor(GLFWwindow* w, double x, double y) {
  Input* in = of(w);
  const double dx = x - in->last_x, dy = y - in->last_y;
  in->last_x = x;
  in->last_y = y;
  if (in->orbiting) in->camera->orbit(dx, dy);
  if (in->dragging) {
    // In the view plane, at the target's depth: a pixel there is this many world units.
    const Camera& c = *in->camera;
    const double per_pixel = 2.0 * c.distance * std::tan(0.5 * c.fov_y) / in->window_height;
    const glm::dvec3 forward = glm::normalize(c.target - c.eye());
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    in->tool_drag += per_pixel * (dx * right - dy * up);
  }
}

void on_scroll(GLFWwindow* w, double, double dy) { of(w)->camera->zoom(dy); }

void on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  Input* in = of(w);
  Show& s = *in->show;
  switch (key) {
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(w, GLFW_TRUE);
      break;
    case GLFW_KEY_1:
      s.meshes = !s.meshes;
      break;
    case GLFW_KEY_2:
      s.strings = !s.strings;
      break;
    case GLFW_KEY_3:
      s.polylines = !s.polylines;
      break;
    case GLFW_KEY_4:
      s.force = !s.force;
      break;
    case GLFW_KEY_5:
      s.hud = !s.hud;
      break;
    case GLFW_KEY_6:
      s.grid = !s.grid;
      break;
    case GLFW_KEY_M:
      in->switch_method = true;
      break;
    case GLFW_KEY_F:
      in->switch_force = true;
      break;
    default:
      break;
  }
}

}  // namespace

int find_gamepad() {
  for (int jid = GLFW_JOYSTICK_1; jid <= GLFW_JOYSTICK_LAST; ++jid)
    if (glfwJoystickIsGamepad(jid)) return jid;
  return -1;
}

bool apply_gamepad(int gamepad, const Camera& camera, double seconds, proxPose* pose) {
  GLFWgamepadstate state;
  if (gamepad < 0 || !glfwGetGamepadState(gamepad, &state)) return false;
  auto axis = [&](int a) {
    const double v = state.axes[a];
    return std::abs(v) < 0.15 ? 0.0 : (v - std::copysign(0.15, v)) / 0.85;
  };
  auto trigger = [&](int a) { return std::max(0.0, 0.5 * (static_cast<double>(state.axes[a]) + 1.0)); };
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye());
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double speed = 0.5 * camera.scene_radius * seconds, turn = seconds;
  // GLFW's y axes point down when pushed forward: forward is up on the screen.
  const glm::dvec3 move =
      speed *
      (axis(GLFW_GAMEPAD_AXIS_LEFT_X) * right - axis(GLFW_GAMEPAD_AXIS_LEFT_Y) * up +
       (trigger(GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER) - trigger(GLFW_GAMEPAD_AXIS_LEFT_TRIGGER)) * forward);
  pose->position.x += move.x;
  pose->position.y += move.y;
  pose->position.z += move.z;
  const glm::dquat spin = glm::angleAxis(turn * axis(GLFW_GAMEPAD_AXIS_RIGHT_X), up) *
                          glm::angleAxis(turn * axis(GLFW_GAMEPAD_AXIS_RIGHT_Y), right);
  const glm::dquat q = glm::normalize(
      spin * glm::dquat(pose->rotation.w, pose->rotation.x, pose->rotation.y, pose->rotation.z));
  pose->rotation = {q.w, q.x, q.y, q.z};
  return true;
}

void attach_input(GLFWwindow* window, Input* input) {
  glfwSetWindowUserPointer(window, input);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetScrollCallback(window, on_scroll);
  glfwSetKeyCallback(window, on_key);
}

}  // namespace viewer
