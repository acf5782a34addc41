// Deforming meshes (docs/dynamic-scenes.md): a refitted hierarchy bounds
// what it must, and the precise search on it finds exactly what it finds on
// a hierarchy built afresh for the deformed mesh, and what the brute-force
// reference finds.
#include "common/worker_pool.h"
#include "support/scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace prox::testing {
namespace {

constexpr double kCutoff = 0.005;  // 5 mm on a 0.155 m bunny

std::shared_ptr<const Model> bunny() {
  static const std::shared_ptr<const Model> model = load_obj_model("bunny.obj");
  return model;
}

// The mesh's vertices under a travelling wave: each moved along y by
// amplitude * sin(2 pi x / wavelength + phase), a smooth bend that neither
// keeps distances nor normals.
std::vector<double> waved(const Mesh& mesh, double amplitude, double wavelength, double phase) {
  std::vector<double> xyz;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.vertex(v);
    xyz.insert(xyz.end(), {p.x, p.y + amplitude * std::sin(2.0 * kPi * p.x / wavelength + phase), p.z});
  }
  return xyz;
}

// The deformed model twice: its hierarchy refitted from `base`'s, and built anew.
struct Deformed {
  Model refitted, rebuilt;
};

Deformed deform(const Model& base, const std::vector<double>& xyz) {
  Deformed d;
  d.refitted.mesh = base.mesh;
  const Status s = d.refitted.mesh.set_vertices(xyz.data(), base.mesh.vertex_count());
  EXPECT_TRUE(s) << s.message();
  d.refitted.snch = std::make_unique<Snch>(*base.snch);
  d.refitted.snch->refit(d.refitted.mesh);
  d.refitted.size = base.size;
  d.refitted.centre = base.centre;
  d.rebuilt.mesh = d.refitted.mesh;
  d.rebuilt.snch = std::make_unique<Snch>(d.rebuilt.mesh);
  d.rebuilt.size = base.size;
  d.rebuilt.centre = base.centre;
  return d;
}

// The triangles below node i.
void triangles_below(const Snch& snch, std::uint32_t i, std::vector<std::uint32_t>& out) {
  const SnchNode& n = snch.node(i);
  if (n.is_leaf()) {
    out.push_back(n.first);
    return;
  }
  triangles_below(snch, n.first, out);
  triangles_below(snch, n.second, out);
}

// What a node must bound, checked from the mesh alone: every node holds the
// triangles below it in its sphere and box; a leaf's cone holds the normal
// of every triangle sharing a vertex with it, an inner node's its
// children's cones.
// A cone's half-angle from the cosine and sine the node keeps.
double half_angle(const CosCone& c) { return std::atan2(c.sin, c.cos); }

// Node i's slab against the vertices of `below`, its triangles: each failure
// reported, and counted.
int slab_failures(const Mesh& mesh, const Snch& snch, std::uint32_t i, const std::vector<std::uint32_t>& below,
                  double eps) {
  const SnchNode& n = snch.node(i);
  const SnchSlab& slab = snch.slab(i);
  int failures = 0;
  for (const std::uint32_t t : below)
    for (const Vec3& v : mesh.triangle(t).v) {
      const double along = glm::dot(v - n.center, n.cone.axis);
      if (along < slab.lo - eps || along > slab.hi + eps)
        ++failures, ADD_FAILURE() << "node " << i << " slab misses triangle " << t;
    }
  return failures;
}

// A built tree's slabs along its cones' axes hold every vertex below them.
void expect_slabs_hold(const Mesh& mesh, const Snch& snch) {
  ASSERT_TRUE(snch.has_slabs());
  const double eps = 1e-12 * mesh.longest_edge();
  int failures = 0;
  std::vector<std::uint32_t> below;
  for (std::uint32_t i = 0; i < snch.nodes().size() && failures < 5; ++i) {
    below.clear();
    triangles_below(snch, i, below);
    failures += slab_failures(mesh, snch, i, below, eps);
  }
}

void expect_bounds_hold(const Mesh& mesh, const Snch& snch) {
  const double eps = 1e-12 * mesh.longest_edge();
  int failures = 0;
  std::vector<std::uint32_t> below;
  for (std::uint32_t i = 0; i < snch.nodes().size() && failures < 5; ++i) {
    const SnchNode& n = snch.node(i);
    const SnchBox& b = snch.box(i);
    const auto in_box = [&](const Vec3& p, double r) {
      const Vec3 d = glm::abs(p - b.center);
      return d.x + r <= b.half.x + eps && d.y + r <= b.half.y + eps && d.z + r <= b.half.z + eps;
    };
    below.clear();
    triangles_below(snch, i, below);
    if (snch.has_slabs()) failures += slab_failures(mesh, snch, i, below, eps);
    if (n.is_leaf()) {
      for (const Vec3& v : mesh.triangle(n.first).v) {
        if (glm::length(v - n.center) > n.radius + eps) ++failures, ADD_FAILURE() << "leaf " << i << " sphere";
        if (!in_box(v, 0.0)) ++failures, ADD_FAILURE() << "leaf " << i << " box";
      }
      if (n.cone.unbounded()) continue;
      for (std::uint32_t v : mesh.indices(n.first))
        for (const std::uint32_t* t = mesh.vertex_triangles_begin(v); t != mesh.vertex_triangles_end(v); ++t) {
          const Vec3& normal = mesh.face_normal(*t);
          if (glm::dot(normal, normal) > 0.0 && angle_between(n.cone.axis, normal) > half_angle(n.cone))
            ++failures, ADD_FAILURE() << "leaf " << i << " cone misses triangle " << *t << "'s normal";
        }
      continue;
    }
    for (const std::uint32_t t : below)
      for (const Vec3& v : mesh.triangle(t).v) {
        if (glm::length(v - n.center) > n.radius + eps)
          ++failures, ADD_FAILURE() << "node " << i << " sphere misses triangle " << t;
        if (!in_box(v, 0.0)) ++failures, ADD_FAILURE() << "node " << i << " box misses triangle " << t;
      }
    for (const std::uint32_t c : {n.first, n.second}) {
      const SnchNode& child = snch.node(c);
      if (!n.cone.unbounded() &&
          (child.cone.unbounded() ||
           angle_between(n.cone.axis, child.cone.axis) + half_angle(child.cone) > half_angle(n.cone) + 1e-12))
        ++failures, ADD_FAILURE() << "node " << i << " cone misses child " << c;
    }
  }
}

using PairKey = std::tuple<std::uint32_t, std::uint32_t, double>;
std::vector<PairKey> keys(const std::vector<LmdPair>& lmds) {
  std::vector<PairKey> out;
  for (const LmdPair& p : lmds) out.emplace_back(p.tri_a, p.tri_b, p.distance);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Refit, AnUnmovedMeshRefitsToDegradationOne) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  EXPECT_EQ(model->snch->stats().degradation, 1.0);
  std::vector<double> same;
  for (std::uint32_t v = 0; v < model->mesh.vertex_count(); ++v)
    for (int c = 0; c < 3; ++c) same.push_back(model->mesh.vertex(v)[c]);
  const Deformed d = deform(*model, same);
  EXPECT_EQ(d.refitted.snch->stats().refits, 1u);
  EXPECT_DOUBLE_EQ(d.refitted.snch->stats().degradation, 1.0);
  expect_bounds_hold(d.refitted.mesh, *d.refitted.snch);
}

TEST(Refit, BoundsHoldAndTheSearchIsTheFreshTreesAndTheReferences) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log_gap(std::log(1e-4), std::log(kCutoff));
  const double tolerance = 1e-9 * model->size;
  Match total;
  int compared = 0;
  // A wave of 5 mm amplitude along the bunny's 15 cm, at four phases; the
  // moving bunny is the deformed one, against an undeformed one.
  for (int k = 0; k < 4; ++k) {
    const Deformed d = deform(*model, waved(model->mesh, 0.005, 0.08, 0.5 * kPi * k));
    // A refitted tree drops the slabs its build measured; a rebuilt one has
    // them again, and they hold the moved triangles.
    EXPECT_FALSE(d.refitted.snch->has_slabs());
    EXPECT_TRUE(d.rebuilt.snch->has_slabs());
    expect_bounds_hold(d.refitted.mesh, *d.refitted.snch);
    expect_slabs_hold(d.rebuilt.mesh, *d.rebuilt.snch);
    EXPECT_LT(d.refitted.snch->stats().degradation, Snch::kRebuildDegradation) << "a bend is refitted";
    for (int i = 0; i < sampled_poses(16); ++i) {
      const Pose pose = pose_at_gap(*model, d.rebuilt, std::exp(log_gap(rng)), rng);
      PairState s1, s2, s3;
      ProximityResult on_refit, on_fresh, ref;
      find_lmds(make_query(*model, Pose{}, d.refitted, pose, kCutoff), Method::Precise, s1, on_refit);
      find_lmds(make_query(*model, Pose{}, d.rebuilt, pose, kCutoff), Method::Precise, s2, on_fresh);
      find_lmds(make_query(*model, Pose{}, d.rebuilt, pose, kCutoff), Method::Reference, s3, ref);
      EXPECT_EQ(keys(on_refit.lmds), keys(on_fresh.lmds)) << "phase " << k << " pose " << i;
      const Match m = match_lmds(ref.lmds, on_refit.lmds, tolerance);
      total.reference += m.reference, total.found += m.found;
      total.recalled += m.recalled, total.confirmed += m.confirmed;
      ++compared;
    }
  }
  std::printf("[ refit ] %d poses on 4 bent bunnies, %d reference LMDs: recall %.4f precision %.4f\n", compared,
              total.reference, double(total.recalled) / total.reference,
              double(total.confirmed) / total.found);
  EXPECT_GT(total.reference, 10);
  EXPECT_EQ(total.recalled, total.reference);
  EXPECT_EQ(total.confirmed, total.found);
}

// The same bits from one thread and from several: each node and each
// normal is computed as the serial refit computes it, and every node is
// refitted once (a node missed keeps its old, wrong bounds).
TEST(Refit, OnWorkersTheNormalsAndTheTreeAreTheSerialOnesBitForBit) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  const std::vector<double> xyz = waved(model->mesh, 0.005, 0.08, 1.0);
  const Deformed serial = deform(*model, xyz);
  for (unsigned threads : {2u, 3u}) {
    WorkerPool pool(threads);
    Mesh mesh = model->mesh;
    ASSERT_TRUE(mesh.set_vertices(xyz.data(), mesh.vertex_count(), &pool));
    for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
      ASSERT_EQ(mesh.vertex_normal(v), serial.refitted.mesh.vertex_normal(v)) << "vertex " << v;
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t)
      ASSERT_EQ(mesh.face_normal(t), serial.refitted.mesh.face_normal(t)) << "triangle " << t;
    EXPECT_EQ(mesh.longest_edge(), serial.refitted.mesh.longest_edge());
    Snch snch(*model->snch);
    snch.refit(mesh, &pool);
    const Snch& expected = *serial.refitted.snch;
    ASSERT_EQ(snch.nodes().size(), expected.nodes().size());
    for (std::uint32_t i = 0; i < snch.nodes().size(); ++i) {
      const SnchNode &a = snch.node(i), &b = expected.node(i);
      ASSERT_EQ(a.center, b.center) << "node " << i;
      ASSERT_EQ(a.radius, b.radius) << "node " << i;
      ASSERT_EQ(a.cone.axis, b.cone.axis) << "node " << i;
      ASSERT_EQ(a.cone.cos, b.cone.cos) << "node " << i;
      ASSERT_EQ(a.cone.sin, b.cone.sin) << "node " << i;
      ASSERT_EQ(snch.box(i).center, expected.box(i).center) << "node " << i;
      ASSERT_EQ(snch.box(i).half, expected.box(i).half) << "node " << i;
    }
    for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
      ASSERT_TRUE(snch.vertex_spread(v).cos == expected.vertex_spread(v).cos &&
                  snch.vertex_spread(v).sin == expected.vertex_spread(v).sin)
          << "vertex " << v;
    EXPECT_EQ(snch.stats().degradation, expected.stats().degradation);
    expect_bounds_hold(mesh, snch);
  }
}

TEST(Refit, AFoldedMeshDegradesPastTheRebuildLimit) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  // Every vertex mirrored through the bunny's centre plane x = c along x,
  // with the halves swapped: the tree's subtrees now span the bunny.
  std::vector<double> xyz;
  const double c = model->centre.x;
  for (std::uint32_t v = 0; v < model->mesh.vertex_count(); ++v) {
    const Vec3& p = model->mesh.vertex(v);
    const double x = p.x < c ? p.x + 0.5 * model->size : p.x - 0.5 * model->size;
    xyz.insert(xyz.end(), {x, p.y, p.z});
  }
  const Deformed d = deform(*model, xyz);
  expect_bounds_hold(d.refitted.mesh, *d.refitted.snch);
  EXPECT_GT(d.refitted.snch->stats().degradation, Snch::kRebuildDegradation);
}

TEST(Refit, SetVerticesRefusesWhatIsNotTheMeshsShape) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  Mesh mesh = model->mesh;
  std::vector<double> xyz(3 * std::size_t{mesh.vertex_count()}, 0.0);
  Status s = mesh.set_vertices(xyz.data(), mesh.vertex_count() - 1);
  EXPECT_FALSE(s);
  EXPECT_NE(s.message().find("vertices (after welding)"), std::string::npos) << s.message();
  xyz[3 * 17 + 2] = NAN;
  s = mesh.set_vertices(xyz.data(), mesh.vertex_count());
  EXPECT_NE(s.message().find("vertex 17 has a non-finite z"), std::string::npos) << s.message();
  // Nothing changed.
  EXPECT_EQ(mesh.vertex(0), model->mesh.vertex(0));
  EXPECT_EQ(mesh.face_normal(5), model->mesh.face_normal(5));
}

}  // namespace
}  // namespace prox::testing
