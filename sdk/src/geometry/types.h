// Basic geometric types of the engine. All engine geometry is double precision.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace prox {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;

inline constexpr double kPi = 3.14159265358979323846;

// A triangle by value. Vertex order defines the face normal (counter-clockwise
// seen from the side the normal points to) and the edge numbering: edge k joins
// vertex k and vertex (k + 1) % 3.
struct Triangle {
  Vec3 v[3];
};

// The lowest-dimensional part of a triangle that holds a point (or a set of
// points): vertex k, edge k (vertex k to vertex k+1), or the face interior.
enum class FeatureKind : std::uint8_t { Vertex = 0, Edge = 1, Face = 2 };

struct Feature {
  FeatureKind kind = FeatureKind::Face;
  std::uint8_t index = 0;  // vertex or edge number 0..2; 0 for a face

  friend bool operator==(Feature a, Feature b) { return a.kind == b.kind && a.index == b.index; }
  friend bool operator!=(Feature a, Feature b) { return !(a == b); }
};

const char* feature_kind_name(FeatureKind kind);

}  // namespace prox
