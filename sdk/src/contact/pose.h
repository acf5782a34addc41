// Rigid poses: world = rotation * local + translation.
#pragma once

#include "geometry/types.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

namespace prox {

struct Pose {
  glm::dmat3 rotation{1.0};
  Vec3 translation{0.0};

  static Pose from_quaternion(const Vec3& t, double w, double x, double y, double z) {
    return {glm::mat3_cast(glm::normalize(glm::dquat(w, x, y, z))), t};
  }
  Vec3 apply(const Vec3& p) const { return rotation * p + translation; }
  Vec3 rotate(const Vec3& v) const { return rotation * v; }
  Pose inverse() const {
    const glm::dmat3 rt = glm::transpose(rotation);
    return {rt, -(rt * translation)};
  }
  // (this * other)(p) = this(other(p)).
  Pose operator*(const Pose& other) const {
    return {rotation * other.rotation, rotation * other.translation + translation};
  }
};

}  // namespace prox
