#include "devices/hid_motion.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace prox::devices {
namespace {

glm::dquat quat(const double q[4]) { return glm::dquat(q[0], q[1], q[2], q[3]); }

void store(const glm::dquat& q, double out[4]) {
  const glm::dquat n = glm::normalize(q);
  out[0] = n.w, out[1] = n.x, out[2] = n.y, out[3] = n.z;
}

}  // namespace

double shape_axis(double value, double dead_zone, double exponent) {
  if (!std::isfinite(value)) return 0.0;
  const double m = std::fabs(value);
  if (m <= dead_zone) return 0.0;
  const double t = std::fmin((m - dead_zone) / (1.0 - dead_zone), 1.0);
  return std::copysign(std::pow(t, exponent), value);
}

void ToolMotion::reset(const double position[3], const double rotation_in[4], const double local[3]) {
  store(quat(rotation_in), rotation);
  const glm::dvec3 r = quat(rotation) * glm::dvec3(local[0], local[1], local[2]);
  for (int i = 0; i < 3; ++i) reference_local[i] = local[i], reference[i] = position[i] + r[i];
}

void ToolMotion::step(const HidAxes& axes, const MotionSettings& s, double seconds) {
  if (!(seconds > 0.0)) return;
  double shaped[6];
  for (int i = 0; i < 6; ++i) shaped[i] = shape_axis(axes.axis[i], s.dead_zone, s.exponent);
  const glm::dquat to_world = quat(s.device_to_world);
  const glm::dvec3 v = to_world * glm::dvec3(shaped[0], shaped[1], shaped[2]) * s.linear_speed;
  const glm::dvec3 w = to_world * glm::dvec3(shaped[3], shaped[4], shaped[5]) * s.angular_speed;
  for (int i = 0; i < 3; ++i) reference[i] += v[i] * seconds;
  const double angle = glm::length(w) * seconds;
  if (angle > 0.0) {
    const glm::dvec3 axis = glm::normalize(w);
    const glm::dquat turn(std::cos(angle / 2), axis * std::sin(angle / 2));
    store(turn * quat(rotation), rotation);  // about a world axis through the reference point
  }
}

void ToolMotion::place(const ToolMotion& home, const MotionSettings& s, const double offset[3],
                       const double axis[3], double angle) {
  *this = home;
  const glm::dquat to_world = quat(s.device_to_world);
  const glm::dvec3 d = to_world * glm::dvec3(offset[0], offset[1], offset[2]);
  for (int i = 0; i < 3; ++i) reference[i] += d[i];
  const glm::dvec3 a(axis[0], axis[1], axis[2]);
  if (angle != 0.0 && glm::length(a) > 0.0) {
    const glm::dvec3 w = glm::normalize(to_world * a);
    const glm::dquat turn(std::cos(angle / 2), w * std::sin(angle / 2));
    store(turn * quat(home.rotation), rotation);
  }
}

void ToolMotion::pose(double position[3], double rotation_out[4]) const {
  const glm::dvec3 r =
      quat(rotation) * glm::dvec3(reference_local[0], reference_local[1], reference_local[2]);
  for (int i = 0; i < 3; ++i) position[i] = reference[i] - r[i];
  for (int i = 0; i < 4; ++i) rotation_out[i] = rotation[i];
}

}  // namespace prox::devices
