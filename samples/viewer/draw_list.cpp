#include "draw_list.h"

#include <algorithm>
#include <cmath>

namespace viewer {

const glm::vec4 kPolylineColor(1.0f, 0.0f, 1.0f, 1.0f);
const glm::vec4 kForceColor(1.0f, 1.0f, 1.0f, 1.0f);
const glm::vec4 kTorqueColor(0.0f, 0.9f, 1.0f, 1.0f);
const glm::vec4 kGridColor(0.35f, 0.36f, 0.40f, 1.0f);
const glm::vec4 kToolColor(0.45f, 0.62f, 0.95f, 1.0f);
const glm::vec4 kOtherColor(0.80f, 0.78f, 0.72f, 1.0f);
// The tool's colour, see-through: where the device holds a constrained tool.
const glm::vec4 kGhostColor(0.45f, 0.62f, 0.95f, 0.3f);
const glm::vec4 kBackground(0.12f, 0.13f, 0.15f, 1.0f);

void add_segment(std::vector<LinePoint>& out, const glm::dvec3& a, const glm::dvec3& b, float width,
                 const glm::vec4& color) {
  out.push_back({glm::vec3(a), width, color});
  out.push_back({glm::vec3(b), width, color});
}

glm::vec4 string_color(double distance, double safety, double cutoff) {
  const double t = cutoff > safety ? std::clamp((distance - safety) / (cutoff - safety), 0.0, 1.0) : 0.0;
  // t = 0 (at the safety distance): red; 0.5: yellow; 1 (the cutoff): green.
  const float r = t < 0.5 ? 1.0f : static_cast<float>(2.0 * (1.0 - t));
  const float g = t < 0.5 ? static_cast<float>(2.0 * t) : 1.0f;
  return {r, g, 0.0f, 1.0f};
}

namespace {

// A "nice" grid step near x: 1, 2 or 5 times a power of ten.
double nice_step(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  const double m = x / p;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

void add_arrow(std::vector<LinePoint>& out, const glm::dvec3& from, const glm::dvec3& vec,
               const glm::dvec3& eye, float width, const glm::vec4& color) {
  const double len = glm::length(vec);
  if (!(len > 0.0)) return;
  const glm::dvec3 dir = vec / len, tip = from + vec;
  glm::dvec3 side = glm::cross(dir, eye - tip);
  side = glm::length(side) > 0.0 ? glm::normalize(side) : glm::dvec3(0.0, 1.0, 0.0);
  const double head = 0.25 * len;
  add_segment(out, from, tip, width, color);
  add_segment(out, tip, tip - head * dir + 0.5 * head * side, width, color);
  add_segment(out, tip, tip - head * dir - 0.5 * head * side, width, color);
}

}  // namespace

void add_scene_lines(DrawList& list, const FrameData& frame, const Scene& scene, const Show& show,
                     const Camera& camera) {
  std::vector<LinePoint>& out = list.world;
  const double r = camera.scene_radius;
  if (show.grid) {
    const glm::dvec3 lo = scene.bounds_min();
    const double step = nice_step(r / 4.0);
    const double y = lo.y;
    const double x0 = std::floor((camera.target.x - 1.5 * r) / step) * step;
    const double z0 = std::floor((camera.target.z - 1.5 * r) / step) * step;
    const int n = static_cast<int>(std::ceil(3.0 * r / step)) + 1;
    for (int i = 0; i <= n; ++i) {
      add_segment(out, {x0 + i * step, y, z0}, {x0 + i * step, y, z0 + n * step}, 1.0f, kGridColor);
      add_segment(out, {x0, y, z0 + i * step}, {x0 + n * step, y, z0 + i * step}, 1.0f, kGridColor);
    }
    // The world axes at the origin, lifted to the grid: x, y, z in muted red, green, blue.
    const double a = 0.5 * r;
    const glm::dvec3 o(0.0, y, 0.0);
    add_segment(out, o, o + glm::dvec3(a, 0.0, 0.0), 2.0f, {0.7f, 0.3f, 0.3f, 1.0f});
    add_segment(out, o, o + glm::dvec3(0.0, a, 0.0), 2.0f, {0.3f, 0.7f, 0.3f, 1.0f});
    add_segment(out, o, o + glm::dvec3(0.0, 0.0, a), 2.0f, {0.3f, 0.4f, 0.8f, 1.0f});
  }
  if (show.strings) {
    const std::vector<double> shares = scene.force_shares(frame.contacts, frame.patches);
    for (std::size_t i = 0; i < frame.contacts.size(); ++i) {
      const proxContact& c = frame.contacts[i];
      const float width = kStringWidthMin + kStringWidthGain * static_cast<float>(shares[i]);
      add_segment(out, {c.pointTool.x, c.pointTool.y, c.pointTool.z},
                  {c.pointOther.x, c.pointOther.y, c.pointOther.z}, width,
                  string_color(c.distance, scene.force().safetyDistance, scene.cutoff()));
    }
  }
  if (show.polylines) {
    for (const Polyline& line : frame.polylines) {
      const std::size_t n = line.points.size();
      for (std::size_t k = 0; k + 1 < n; ++k)
        add_segment(out, line.points[k], line.points[k + 1], kPolylineWidth, kPolylineColor);
      if (line.closed && n > 2)
        add_segment(out, line.points[n - 1], line.points[0], kPolylineWidth, kPolylineColor);
    }
  }
  if (show.force) {
    // Lengths: half the scene's radius at the maximum force or torque.
    const proxVec3& f = frame.wrench.force;
    const proxVec3& t = frame.wrench.torque;
    const glm::dvec3 eye = camera.eye();
    add_arrow(out, frame.reference_point, glm::dvec3(f.x, f.y, f.z) * (0.5 * r / scene.force().maxForce), eye,
              3.0f, kForceColor);
    add_arrow(out, frame.reference_point, glm::dvec3(t.x, t.y, t.z) * (0.5 * r / scene.force().maxTorque),
              eye, 2.0f, kTorqueColor);
  }
}

}  // namespace viewer
