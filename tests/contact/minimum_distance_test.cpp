// minimum_distance (behind proxBody_GetDistance) and any_closer_than against
// the brute-force reference, on CAD parts with long thin triangles and on the
// bunny; and the SNCH's boxes, which both searches cull with.
#include "support/scenes.h"

#include "contact/descent.h"
#include "contact/global_search.h"
#include "geometry/triangle_distance.h"

#include <gtest/gtest.h>
#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace prox::testing {
namespace {

struct Pair {
  const char* name;
  std::shared_ptr<const Model> a, b;
};

std::vector<Pair> pairs() {
  // 2CylinderEngine's cylinder block and crankcase, ReciprocatingSaw's two
  // housing halves (PerNode order), and the bunny against itself.
  return {
      {"2CylinderEngine parts", load_gltf_model("gltf/2CylinderEngine.glb", 9),
       load_gltf_model("gltf/2CylinderEngine.glb", 8)},
      {"ReciprocatingSaw halves", load_gltf_model("gltf/ReciprocatingSaw.glb", 0),
       load_gltf_model("gltf/ReciprocatingSaw.glb", 2)},
      {"bunny", load_obj_model("bunny.obj"), load_obj_model("bunny.obj")},
  };
}

// The triangles below node i, in the tree's order.
std::vector<std::uint32_t> triangles_below(const Snch& snch, std::uint32_t i) {
  std::vector<std::uint32_t> out, stack{i};
  while (!stack.empty()) {
    const SnchNode& n = snch.node(stack.back());
    stack.pop_back();
    if (n.is_leaf()) {
      out.push_back(n.first);
    } else {
      stack.push_back(n.second);
      stack.push_back(n.first);
    }
  }
  return out;
}

// The minimum distance is the smallest LMD distance; the reference finds
// every LMD within the cutoff with the same exact kernel, so the two agree
// up to the rounding between tied triangle pairs (1e-18 of the size).
TEST(MinimumDistance, MatchesTheReferenceOnCadPartsAndTheBunny) {
  PairState state;
  for (const Pair& pair : pairs()) {
    ASSERT_TRUE(pair.a && pair.b) << pair.name;
    const double size = std::max(pair.a->size, pair.b->size);
    const double cutoff = 0.03 * size;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> log_gap(std::log(1e-4 * size), std::log(cutoff));
    for (int i = 0; i < sampled_poses(20); ++i) {
      const Pose pose = pose_at_gap(*pair.a, *pair.b, std::exp(log_gap(rng)), rng);
      const PairQuery q = make_query(*pair.a, Pose{}, *pair.b, pose, cutoff);
      ProximityResult ref;
      find_lmds(q, Method::Reference, state, ref);
      ASSERT_FALSE(ref.lmds.empty()) << pair.name << " pose " << i;
      double expected = std::numeric_limits<double>::infinity();
      for (const LmdPair& p : ref.lmds) expected = std::min(expected, p.distance);
      const double d = minimum_distance(q, std::numeric_limits<double>::infinity());
      const double tolerance = 1e-15 * size;
      EXPECT_NEAR(d, expected, tolerance) << pair.name << " pose " << i;
      // Bounded: nothing closer below the answer, the answer above it.
      EXPECT_GE(minimum_distance(q, 0.999 * expected), expected - tolerance) << pair.name << " pose " << i;
      EXPECT_NEAR(minimum_distance(q, 1.001 * expected), expected, tolerance) << pair.name << " pose " << i;
      EXPECT_TRUE(any_closer_than(q, 1.001 * expected)) << pair.name << " pose " << i;
      EXPECT_FALSE(any_closer_than(q, 0.999 * expected)) << pair.name << " pose " << i;
    }
  }
}

// The least exact distance over every pair of triangles, each pair skipped
// only where the spheres around the two triangles (about their first
// vertex, a little enlarged for rounding) are farther apart than the least
// so far: the brute-force answer, without the trees.
double least_over_every_triangle_pair(const Mesh& a, const Mesh& b, const Pose& b_to_a) {
  struct Ball {
    Vec3 c;
    double r;
  };
  auto balls = [](const Mesh& m, const Pose& pose) {
    std::vector<Ball> out;
    for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
      const Triangle tri = detail::moved(m.triangle(t), pose);
      const double r = std::max(glm::length(tri.v[1] - tri.v[0]), glm::length(tri.v[2] - tri.v[0]));
      out.push_back({tri.v[0], r * (1.0 + 1e-12)});
    }
    return out;
  };
  const std::vector<Ball> ba = balls(a, Pose{}), bb = balls(b, b_to_a);
  double least = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < ba.size(); ++i)
    for (std::uint32_t j = 0; j < bb.size(); ++j) {
      const double reach = ba[i].r + bb[j].r + least;
      const Vec3 d = bb[j].c - ba[i].c;
      if (glm::dot(d, d) > reach * reach * (1.0 + 1e-12)) continue;
      const Triangle tb = detail::moved(b.triangle(j), b_to_a);
      least = std::min(least, geometry::triangle_distance(a.triangle(i), tb).distance);
    }
  return least;
}

// Far from contact, where thousands of node pairs are nearer than the answer
// and the search turns from best first to depth first, the answer is still
// the least over every triangle pair, Suzanne against the Duck turned every
// which way, from a hundredth to half their size apart.
TEST(MinimumDistance, FarFromContactItIsTheLeastOverEveryTrianglePair) {
  const auto a = load_gltf_model("gltf/Suzanne/Suzanne.gltf");
  const auto b = load_gltf_model("gltf/Duck.glb");
  ASSERT_TRUE(a && b);
  const double size = std::max(a->size, b->size);
  std::mt19937_64 rng(17);
  int checked = 0;
  for (const double gap : {0.01, 0.05, 0.2, 0.5}) {
    for (int i = 0; i < sampled_poses(3); ++i) {
      const Pose pose = pose_at_gap(*a, *b, gap * size, rng);
      const PairQuery q = make_query(*a, Pose{}, *b, pose, 0.0);
      const double expected = least_over_every_triangle_pair(a->mesh, b->mesh, detail::Frames(q).b_to_a);
      ASSERT_GT(expected, 0.5 * gap * size) << "gap " << gap << " pose " << i;
      const double tolerance = 1e-15 * size;
      EXPECT_NEAR(minimum_distance(q, std::numeric_limits<double>::infinity()), expected, tolerance)
          << "gap " << gap << " pose " << i;
      EXPECT_NEAR(minimum_distance(q, 1.001 * expected), expected, tolerance) << "gap " << gap << " pose " << i;
      EXPECT_EQ(minimum_distance(q, 0.999 * expected), std::numeric_limits<double>::infinity())
          << "gap " << gap << " pose " << i;
      EXPECT_TRUE(any_closer_than(q, 1.001 * expected)) << "gap " << gap << " pose " << i;
      EXPECT_FALSE(any_closer_than(q, 0.999 * expected)) << "gap " << gap << " pose " << i;
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);
}

// Every node's box holds the vertices of every triangle below it.
TEST(Snch, BoxesHoldTheirTriangles) {
  for (const Pair& pair : pairs()) {
    ASSERT_TRUE(pair.a) << pair.name;
    const Snch& snch = *pair.a->snch;
    const Mesh& mesh = pair.a->mesh;
    std::size_t checked = 0;
    for (std::uint32_t i = 0; i < snch.nodes().size(); i += 7) {  // a sample of nodes, leaves and inner
      const SnchBox& box = snch.box(i);
      for (std::uint32_t t : triangles_below(snch, i))
        for (const Vec3& v : mesh.triangle(t).v) {
          const Vec3 off = glm::abs(v - box.center);
          ASSERT_TRUE(off.x <= box.half.x && off.y <= box.half.y && off.z <= box.half.z)
              << pair.name << " node " << i << " triangle " << t;
        }
      ++checked;
    }
    EXPECT_GT(checked, 0u) << pair.name;
  }
}

// Every node's slab along its cone's axis holds the vertices of every
// triangle below it, on the long thin triangles of the CAD parts too.
TEST(Snch, SlabsHoldTheirTriangles) {
  for (const Pair& pair : pairs()) {
    ASSERT_TRUE(pair.a) << pair.name;
    const Snch& snch = *pair.a->snch;
    const Mesh& mesh = pair.a->mesh;
    ASSERT_TRUE(snch.has_slabs()) << pair.name;
    const double eps = 1e-12 * pair.a->size;
    std::size_t checked = 0, thin = 0;
    for (std::uint32_t i = 0; i < snch.nodes().size(); i += 7) {
      const SnchNode& n = snch.node(i);
      const SnchSlab& slab = snch.slab(i);
      for (std::uint32_t t : triangles_below(snch, i))
        for (const Vec3& v : mesh.triangle(t).v) {
          const double along = glm::dot(v - n.center, n.cone.axis);
          ASSERT_TRUE(along >= slab.lo - eps && along <= slab.hi + eps) << pair.name << " node " << i;
        }
      ++checked;
      thin += slab.hi - slab.lo < 0.5 * n.radius ? 1 : 0;
    }
    EXPECT_GT(checked, 0u) << pair.name;
    // Thinner than the spheres at a tenth of the nodes at least (about a
    // fifth on the engine's cylinder block), or they would bound nothing the
    // spheres do not.
    EXPECT_GT(thin, checked / 10) << pair.name << ": " << thin << " of " << checked;
  }
}

// The closest-pair search's bound on a node pair (spheres, A's box
// against the box along A's axes around B's, and the slabs) against brute force: never
// above the least exact distance between the triangles below the two
// nodes. Node pairs are taken on dives from the roots towards the closer
// children (mostly), where the bounds are tightest, at poses from touching
// to a fifth of the size apart.
TEST(MinimumDistance, TheNodePairBoundIsNeverAboveTheTrianglesBelowIt) {
  for (const Pair& pair : pairs()) {
    ASSERT_TRUE(pair.a && pair.b) << pair.name;
    const double size = std::max(pair.a->size, pair.b->size);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0, tight = 0;
    for (const double gap : {1e-4, 1e-2, 0.2}) {
      const Pose pose = pose_at_gap(*pair.a, *pair.b, gap * size, rng);
      const PairQuery q = make_query(*pair.a, Pose{}, *pair.b, pose, 0.0);
      const detail::Frames frames(q);
      for (int dive = 0; dive < sampled_poses(60); ++dive) {
        std::uint32_t ia = 0, ib = 0;
        while (true) {
          const std::vector<std::uint32_t> below_a = triangles_below(*q.snch_a, ia);
          const std::vector<std::uint32_t> below_b = triangles_below(*q.snch_b, ib);
          if (below_a.size() * below_b.size() <= 256) {
            double least = std::numeric_limits<double>::infinity();
            for (std::uint32_t ta : below_a)
              for (std::uint32_t tb : below_b)
                least = std::min(least, geometry::triangle_distance(q.mesh_a->triangle(ta),
                                                                    detail::moved(q.mesh_b->triangle(tb),
                                                                                  frames.b_to_a))
                                            .distance);
            const double bound = detail::node_pair_distance_bound(q, frames, ia, ib);
            ASSERT_LE(bound, least + 1e-15 * size) << pair.name << " gap " << gap << " nodes " << ia << ", " << ib;
            // With a limit: the same bound up to it, and past it something
            // past it (the search drops the pair either way).
            ASSERT_EQ(detail::node_pair_distance_bound(q, frames, ia, ib, bound), bound) << pair.name;
            if (bound > 0.0) {
              ASSERT_GT(detail::node_pair_distance_bound(q, frames, ia, ib, 0.5 * bound), 0.5 * bound) << pair.name;
            }
            ++checked;
            tight += bound > 0.9 * least ? 1 : 0;
          }
          const SnchNode &na = q.snch_a->node(ia), &nb = q.snch_b->node(ib);
          if (na.is_leaf() && nb.is_leaf()) break;
          // The two child pairs; the closer by the bound, four times in five.
          std::uint32_t next[2][2];
          int n = 0;
          detail::for_child_pairs(*q.snch_a, *q.snch_b, ia, ib, [&](std::uint32_t a, std::uint32_t b) {
            next[n][0] = a, next[n][1] = b, ++n;
          });
          const bool first_closer = detail::node_pair_distance_bound(q, frames, next[0][0], next[0][1]) <=
                                    detail::node_pair_distance_bound(q, frames, next[1][0], next[1][1]);
          const int pick = (unit(rng) < 0.8) == first_closer ? 0 : 1;
          ia = next[pick][0], ib = next[pick][1];
        }
      }
    }
    EXPECT_GT(checked, 100) << pair.name;
    // Tight enough somewhere that a bound a tenth too high would show.
    EXPECT_GT(tight, 10) << pair.name;
  }
}

// Triangles 1e-122 across (and a coordinate of 1e-322) beside ones of a few
// units, from a fuzzed input (tests/fuzz/regressions/create_mesh): their
// circumcentres came out 0 / 0, the NaN spread up the tree, and every node
// pair compared false, so the mesh was never nearer itself than infinity.
TEST(MinimumDistance, TinyTrianglesBesideLargeOnesKeepTheTreeFinite) {
  const std::vector<double> p = {-19.854, -19.854, -12.855, -1.7132422564468183e-122, -1.7132422564468183e-122,
                                 -1.7132422564468183e-122, -1.7132422564468183e-122, 3.0429479402230786e-144, 0.0,
                                 0.0, 13.485, 0.0, 0.0, 3.425, 0.0, 0.0, 0.0, 1.7292297604443629e-322, 0.0, 0.0, 5.84};
  const std::vector<std::uint32_t> idx = {0, 4, 2, 2, 5, 1, 2, 4, 5, 4, 0, 5, 5, 3, 6, 6, 4, 0, 5, 1, 2, 2, 6, 4};
  Status s;
  const Mesh m = Mesh::build({p.data(), 7, idx.data(), static_cast<std::uint32_t>(idx.size() / 3)}, s);
  ASSERT_TRUE(s) << s.message();
  const Snch snch(m);
  for (std::uint32_t i = 0; i < snch.nodes().size(); ++i) {
    const SnchNode& n = snch.node(i);
    ASSERT_TRUE(std::isfinite(n.center.x) && std::isfinite(n.center.y) && std::isfinite(n.center.z) &&
                std::isfinite(n.radius))
        << "node " << i;
    if (!n.is_leaf()) continue;
    for (const Vec3& v : m.triangle(n.first).v) {
      const Vec3 d = v - n.center;
      // To rounding relative to the leaf's own size, however small.
      EXPECT_LE(std::hypot(d.x, d.y, d.z), n.radius * (1.0 + 1e-12))
          << "leaf " << i << " misses a vertex of triangle " << n.first;
    }
  }
  const PairQuery q{&m, &snch, Pose{}, &m, &snch, Pose{}, 0.0};
  EXPECT_EQ(minimum_distance(q, std::numeric_limits<double>::infinity()), 0.0);
  // Moved 1 unit apart along x: a finite distance, at most the move.
  const PairQuery apart{&m, &snch, Pose{}, &m, &snch, Pose{glm::dmat3(1.0), Vec3(1.0, 0.0, 0.0)}, 0.0};
  const double d = minimum_distance(apart, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isfinite(d) && d >= 0.0 && d <= 1.0) << d;
}

}  // namespace
}  // namespace prox::testing
