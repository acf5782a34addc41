// What the lines pipeline draws: segments as pairs of points (the layout of
// shaders/lines.vert's storage buffer), built from a frame's data.
#pragma once

#include "camera.h"
#include "options.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace viewer {

struct LinePoint {
  glm::vec3 position;  // world, or pixels for the HUD
  float width;         // pixels
  glm::vec4 color;     // linear 0-1
};
static_assert(sizeof(LinePoint) == 32, "the std430 layout of shaders/lines.vert");

struct DrawList {
  std::vector<LinePoint> world;   // depth-tested with the meshes
  std::vector<LinePoint> screen;  // the HUD, in pixels, on top
};

void add_segment(std::vector<LinePoint>& out, const glm::dvec3& a, const glm::dvec3& b, float width,
                 const glm::vec4& color);

// The colours, chosen so that no two kinds share one: strings run from
// green (at the cutoff) through yellow to red (at the safety distance) and
// never have blue; polylines are magenta, the force white, the torque cyan.
glm::vec4 string_color(double distance, double safety, double cutoff);
extern const glm::vec4 kPolylineColor, kForceColor, kTorqueColor, kGridColor, kToolColor, kOtherColor,
    kGhostColor, kBackground;

// String widths in pixels: from kStringWidthMin for a contact with no share
// of the force to kStringWidthMin + kStringWidthGain for one with all of it.
constexpr float kStringWidthMin = 2.0f, kStringWidthGain = 6.0f, kPolylineWidth = 3.0f;

// Strings, polylines, force and torque arrows, grid and axes, as --show asks.
void add_scene_lines(DrawList& list, const FrameData& frame, const Scene& scene, const Show& show,
                     const Camera& camera);

}  // namespace viewer
