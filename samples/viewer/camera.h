// The orbit camera and the matrices a frame uses, in Vulkan's clip
// conventions: right-handed view, y down in normalised device coordinates,
// depth in [0, 1].
#pragma once

#include <glm/glm.hpp>

namespace viewer {

struct Camera {
  glm::dvec3 target{0.0};
  double distance = 1.0;
  double yaw = 0.35, pitch = 0.35;  // radians: about +y, then up from the xz plane
  double fov_y = 0.7;               // radians
  double scene_radius = 1.0;

  // Looks at the box's centre from where all of it fits in the view.
  void frame(const glm::dvec3& lo, const glm::dvec3& hi, double aspect);
  void orbit(double dx_pixels, double dy_pixels);
  void zoom(double wheel_steps);

  glm::dvec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 proj(double aspect) const;
};

}  // namespace viewer
