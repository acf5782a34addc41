#include "scenes.h"

#include "contact/global_search.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace prox::bench {

MeshSource bunny_source() { return {"bunny", "bunny.obj", -1, 1.0, 0, false}; }

namespace {

// The CAD parts, by node in PerNode order (sizes in mm, the file's units):
// 2CylinderEngine node 8 "body_1" (the crankcase, 190 x 271 x 233), node 9
// "body_2" (a cylinder block, 161 x 160 x 190; the part the accuracy tests
// use); ReciprocatingSaw node 0 "body_1" and node 2 "body_5", the two halves
// of the housing (152 x 42 x 147 each, split at y = 0).
MeshSource engine_part(int node, const char* name) {
  return {std::string("engine ") + name, "gltf/2CylinderEngine.glb", node, 0.001, 0, false};
}
MeshSource saw_part(int node, const char* name) {
  return {std::string("saw ") + name, "gltf/ReciprocatingSaw.glb", node, 0.001, 0, false};
}

std::vector<Scene> make_scenes() {
  std::vector<Scene> all;
  auto bunny_scene = [&](const char* name, const char* description, PathKind kind, double near, bool soft,
                         const char* same_as) {
    Scene s;
    s.name = name, s.description = description, s.group = "bunny";
    s.a = s.b = bunny_source();
    s.kind = kind, s.near = near, s.soft = soft, s.same_as = same_as;
    all.push_back(s);
  };
  bunny_scene("path-t",
              "Path T: bunny B translated along +x from 50 mm to 0.5 mm from bunny A, linear in x; "
              "hard force settings, cutoff 5 mm. The paper's hard scene (6.1) is this path.",
              PathKind::Translate, 0.0005, false, "paper-hard");
  bunny_scene(
      "path-r",
      "Path R: bunny B turned by 90 deg * s about normalize(0.3, 1, 0.2) through its centroid "
      "and moved along +x so that the minimum distance is 50 mm * 0.01^s (bisection on x); hard force "
      "settings, cutoff 5 mm.",
      PathKind::Rotate, 0.0005, false, "");
  bunny_scene(
      "paper-hard",
      "The paper's 6.1 benchmark with the hard force settings: path T (50 mm to 0.5 mm), cutoff 5 mm.",
      PathKind::Translate, 0.0005, false, "path-t");
  bunny_scene(
      "paper-soft",
      "The paper's 6.1 benchmark with the soft force settings: bunny B translated along +x from 50 mm to "
      "2 mm from bunny A, linear in x; linear force, cutoff 10 mm.",
      PathKind::Translate, 0.002, true, "");

  // Large and uneven triangles (the paper's case where the original method
  // fails). CAD parts in metres; cutoff 2% of the larger diagonal, the
  // bunny pair's ratio; B moves along a file axis, linear in the offset.
  auto cad_scene = [&](const char* name, const char* description, MeshSource a, MeshSource b, Vec3 direction,
                       bool centre) {
    Scene s;
    s.name = name, s.description = description, s.group = "cad";
    s.a = std::move(a), s.b = std::move(b);
    s.direction = direction, s.centre_b_on_a = centre;
    s.cutoff_over_size = kCadCutoffOverSize;
    all.push_back(s);
  };
  cad_scene(
      "cad-engine",
      "2CylinderEngine parts: the cylinder block (node 9, body_2) pulled out of the crankcase (node 8, "
      "body_1) along +x from where the two are assembled in the file, linear in the offset from 3 to 0.1 "
      "cutoffs; hard force settings scaled to a cutoff of 2% of the larger diagonal.",
      engine_part(8, "body_1"), engine_part(9, "body_2"), Vec3(1.0, 0.0, 0.0), false);
  cad_scene(
      "cad-saw",
      "ReciprocatingSaw housing halves: node 2 (body_5) pulled off node 0 (body_1) along +y from where they "
      "are assembled in the file, linear in the offset from 3 to 0.1 cutoffs; hard force settings scaled "
      "to a cutoff of 2% of the larger diagonal.",
      saw_part(0, "body_1"), saw_part(2, "body_5"), Vec3(0.0, 1.0, 0.0), false);
  cad_scene(
      "cad-bunny-engine",
      "The bunny (B, 27,864 small triangles) against the 2CylinderEngine cylinder block (A, node 9, large "
      "and thin triangles): B's box centre on A's, then along +x, linear in the offset from 3 to 0.1 "
      "cutoffs; hard force settings scaled to a cutoff of 2% of the larger diagonal.",
      engine_part(9, "body_2"), bunny_source(), Vec3(1.0, 0.0, 0.0), true);
  cad_scene(
      "cad-saw-engine",
      "ReciprocatingSaw housing half (B, node 0, body_1) against the 2CylinderEngine cylinder block (A, node "
      "9): B's box centre on A's, then along +z, linear in the offset from 3 to 0.1 cutoffs; hard force "
      "settings scaled to a cutoff of 2% of the larger diagonal.",
      engine_part(9, "body_2"), saw_part(0, "body_1"), Vec3(0.0, 0.0, 1.0), true);

  // Scaling: path T on the bunny at five resolutions, A and B the same mesh.
  // Decimated by scripts/decimate.py (quadric simplification, so the shape
  // and the path move a little); subdivided by 1 -> 4 midpoint splits (the
  // same surface, so the same path and distances).
  struct Level {
    const char* name;
    MeshSource source;
  };
  const Level levels[] = {
      {"scaling-2k", {"bunny 2k (decimated)", "bunny-2k.obj", -1, 1.0, 0, true}},
      {"scaling-7k", {"bunny 7k (decimated)", "bunny-7k.obj", -1, 1.0, 0, true}},
      {"scaling-28k", bunny_source()},
      {"scaling-111k", {"bunny 111k (subdivided once)", "bunny.obj", -1, 1.0, 1, false}},
      {"scaling-446k", {"bunny 446k (subdivided twice)", "bunny.obj", -1, 1.0, 2, false}},
  };
  for (const Level& level : levels) {
    Scene s;
    s.name = level.name, s.group = "scaling";
    s.a = s.b = level.source;
    s.description =
        "Scaling: path T (B along +x from 50 mm to 0.5 mm, hard force settings, cutoff 5 mm) with A and "
        "B both " +
        level.source.label + ".";
    all.push_back(s);
  }
  return all;
}

// The x at which `at(x) = at(0) + x * dir` puts B exactly `gap` from A. The
// minimum distance d(x) changes no faster than x, so from an x where the
// bounding boxes are `gap` apart along dir, steps of x -= d(x) - gap never
// bring B closer than `gap`; head-on they arrive in two or three steps.
// Where they crawl (a grazing approach), a bisection between a closer x and
// the last step finishes. Either way no pair is closer than `gap`, and the
// result is within 1e-12 of the model sizes of the exact x.
template <typename PoseAt>
double x_at_gap(const Model& a, const Model& b, double gap, const Vec3& dir, PoseAt at) {
  const Pose start = at(0.0);
  double reach_a = -kInf, reach_b = kInf;  // A's box forward along dir, B's box backward
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 pa((corner & 1 ? a.mesh.bounds().max : a.mesh.bounds().min).x,
                  (corner & 2 ? a.mesh.bounds().max : a.mesh.bounds().min).y,
                  (corner & 4 ? a.mesh.bounds().max : a.mesh.bounds().min).z);
    const Vec3 pb((corner & 1 ? b.mesh.bounds().max : b.mesh.bounds().min).x,
                  (corner & 2 ? b.mesh.bounds().max : b.mesh.bounds().min).y,
                  (corner & 4 ? b.mesh.bounds().max : b.mesh.bounds().min).z);
    reach_a = std::max(reach_a, glm::dot(pa, dir));
    reach_b = std::min(reach_b, glm::dot(start.apply(pb), dir));
  }
  double lo = 0.0, hi = std::max(0.0, reach_a - reach_b) + gap;
  const double tolerance = 1e-12 * (a.size + b.size);
  double excess = 0.0;
  for (int i = 0; i < 8; ++i) {
    const double d = minimum_distance(make_query(a, b, at(hi), 0.0), kInf) - gap;
    if (!(d > 0.0)) {  // only rounding can do this: back to the last x known to be far enough
      hi += excess;
      break;
    }
    excess = d;
    if (excess <= tolerance) return hi;
    hi -= excess;
  }
  if (!any_closer_than(make_query(a, b, at(lo), 0.0), gap))
    throw UserError(a.name + " / " + b.name + ": the path's offset 0 is not within " + std::to_string(gap) +
                    " m, so the bisection has no bracket");
  // A closer x for the bisection's bracket, in growing steps back from hi
  // (every x that is not closer than `gap` is a better hi).
  for (double step = std::max(excess, tolerance);; step *= 4.0) {
    const double x = std::max(lo, hi - step);
    if (x == lo || any_closer_than(make_query(a, b, at(x), 0.0), gap)) {
      lo = x;
      break;
    }
    hi = x;
  }
  for (int i = 0; i < 100 && hi - lo > tolerance; ++i) {
    const double mid = 0.5 * (lo + hi);
    (any_closer_than(make_query(a, b, at(mid), 0.0), gap) ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

const std::vector<Scene>& scenes() {
  static const std::vector<Scene> all = make_scenes();
  return all;
}

PairQuery make_query(const Model& a, const Model& b, const Pose& pose_b, double cutoff) {
  return {&a.mesh, a.snch.get(), Pose{}, &b.mesh, b.snch.get(), pose_b, cutoff};
}

std::vector<PosePoint> make_path(const Scene& scene, double far, double near, const Model& a, const Model& b,
                                 int n) {
  std::vector<PosePoint> path;
  if (scene.kind == PathKind::Translate) {
    const Vec3 base = scene.centre_b_on_a ? a.box_centre - b.box_centre : Vec3(0.0);
    const Vec3 dir = scene.direction;
    auto at = [&](double x) { return Pose{glm::dmat3(1.0), base + x * dir}; };
    const double x0 = x_at_gap(a, b, far, dir, at), x1 = x_at_gap(a, b, near, dir, at);
    for (int i = 0; i < n; ++i) {
      const double s = n > 1 ? double(i) / double(n - 1) : 1.0;
      PosePoint p;
      p.s = s;
      p.x = x0 + (x1 - x0) * s;
      p.pose = at(p.x);
      p.target_gap = kNaN;  // linear in x, not in the gap
      path.push_back(p);
    }
  } else {
    const Vec3 axis = glm::normalize(Vec3(0.3, 1.0, 0.2));
    const Vec3 c = b.centroid;
    for (int i = 0; i < n; ++i) {
      const double s = n > 1 ? double(i) / double(n - 1) : 1.0;
      const glm::dmat3 r = glm::mat3_cast(glm::angleAxis(0.5 * kPiValue * s, axis));
      const Vec3 base = c - r * c;  // turn about the centroid
      auto at = [&](double x) { return Pose{r, base + Vec3(x, 0.0, 0.0)}; };
      PosePoint p;
      p.s = s;
      p.target_gap = far * std::pow(near / far, s);
      p.x = x_at_gap(a, b, p.target_gap, Vec3(1.0, 0.0, 0.0), at);
      p.pose = at(p.x);
      path.push_back(p);
    }
  }
  return path;
}

}  // namespace prox::bench
