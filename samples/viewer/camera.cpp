#include "camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace viewer {

void Camera::frame(const glm::dvec3& lo, const glm::dvec3& hi, double aspect) {
  target = 0.5 * (lo + hi);
  scene_radius = std::max(0.5 * glm::length(hi - lo), 1e-9);
  // The bounding sphere fits the narrower of the two fields of view.
  const double half = std::min(0.5 * fov_y, std::atan(std::tan(0.5 * fov_y) * aspect));
  distance = 1.05 * scene_radius / std::sin(half);
}

void Camera::orbit(double dx, double dy) {
  yaw -= dx * 0.01;
  pitch = std::clamp(pitch + dy * 0.01, -1.5, 1.5);
}

void Camera::zoom(double steps) {
  distance = std::clamp(distance * std::pow(0.9, steps), 0.05 * scene_radius, 50.0 * scene_radius);
}

glm::dvec3 Camera::eye() const {
  const glm::dvec3 dir(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
  return target + distance * dir;
}

glm::mat4 Camera::view() const { return glm::mat4(glm::lookAt(eye(), target, glm::dvec3(0.0, 1.0, 0.0))); }

glm::mat4 Camera::proj(double aspect) const {
  const double near = std::max(distance - 2.0 * scene_radius, 0.01 * distance);
  const double far = distance + 4.0 * scene_radius;
  glm::dmat4 p = glm::perspectiveRH_ZO(fov_y, aspect, near, far);
  p[1][1] = -p[1][1];  // Vulkan's y points down
  return glm::mat4(p);
}

}  // namespace viewer
