// The precise search split over workers (PairQuery::pool) gives the serial
// search's answer bit for bit: the same candidates in the same order, the
// same counts, and so the same LMDs after the reduction, on the bunny, the
// CAD parts and a flat sheet (where tied candidates make order matter).
#include "common/worker_pool.h"
#include "contact/global_search.h"
#include "contact/proximity.h"
#include "support/scenes.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace prox {
namespace {

using prox::testing::Model;

bool same(const LmdPair& x, const LmdPair& y) {
  return x.tri_a == y.tri_a && x.tri_b == y.tri_b && std::memcmp(&x.point_a, &y.point_a, sizeof x.point_a) == 0 &&
         std::memcmp(&x.point_b, &y.point_b, sizeof x.point_b) == 0 &&
         std::memcmp(&x.distance, &y.distance, sizeof x.distance) == 0;
}

void expect_same_stats(const GlobalSearchStats& s, const GlobalSearchStats& p) {
  EXPECT_EQ(s.node_pairs, p.node_pairs);
  EXPECT_EQ(s.rejected_g1, p.rejected_g1);
  EXPECT_EQ(s.rejected_g2, p.rejected_g2);
  EXPECT_EQ(s.rejected_g3, p.rejected_g3);
  EXPECT_EQ(s.leaf_pairs, p.leaf_pairs);
  EXPECT_EQ(s.plane_rejections, p.plane_rejections);
  EXPECT_EQ(s.visibility_rejections, p.visibility_rejections);
  EXPECT_EQ(s.distance_evaluations, p.distance_evaluations);
  EXPECT_EQ(s.candidates, p.candidates);
  EXPECT_EQ(s.intersecting_pairs, p.intersecting_pairs);
}

// Candidates, counts and reduced LMDs of `poses` of b against a, serial and
// on pools of 2 and 4 threads.
void compare(const Model& a, const Model& b, double cutoff, const std::vector<Pose>& poses, int& candidates) {
  WorkerPool two(2), four(4);
  candidates = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    PairQuery q = make_query(a, Pose{}, b, poses[i], cutoff);
    // Every other pose without the leaf budget; with it (the default), a
    // search over it is searched again in order.
    if (i % 2 == 1) q.patches.leaf_budget = 0;
    std::vector<LmdPair> serial;
    GlobalSearchStats serial_stats;
    global_search_precise(q, serial, serial_stats);
    PairState state;
    ProximityResult serial_lmds;
    find_lmds(q, Method::Precise, state, serial_lmds);
    candidates += static_cast<int>(serial.size());
    for (WorkerPool* pool : {&two, &four}) {
      q.pool = pool;
      std::vector<LmdPair> split;
      GlobalSearchStats split_stats;
      global_search_precise(q, split, split_stats);
      ASSERT_EQ(split.size(), serial.size()) << "pose " << i << ", " << pool->size() << " threads";
      for (std::size_t k = 0; k < split.size(); ++k)
        ASSERT_TRUE(same(split[k], serial[k])) << "pose " << i << ", candidate " << k;
      expect_same_stats(serial_stats, split_stats);
      PairState split_state;
      ProximityResult split_lmds;
      find_lmds(q, Method::Precise, split_state, split_lmds);
      ASSERT_EQ(split_lmds.lmds.size(), serial_lmds.lmds.size()) << "pose " << i;
      for (std::size_t k = 0; k < split_lmds.lmds.size(); ++k)
        EXPECT_TRUE(same(split_lmds.lmds[k], serial_lmds.lmds[k])) << "pose " << i << ", LMD " << k;
      q.pool = nullptr;
    }
  }
}

std::vector<Pose> poses_near(const Model& a, const Model& b, double cutoff, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> gap(0.02 * cutoff, cutoff);
  std::vector<Pose> poses;
  for (int i = 0; i < n; ++i) poses.push_back(pose_at_gap(a, b, gap(rng), rng));
  return poses;
}

TEST(ParallelSearch, SplitOverWorkersTheAnswerIsTheSerialOnesBitForBit) {
  const auto bunny = prox::testing::load_obj_model("bunny.obj");
  ASSERT_TRUE(bunny);
  const double bunny_cutoff = 0.03 * bunny->size;
  int on_bunny = 0, on_cad = 0, on_sheets = 0;
  compare(*bunny, *bunny, bunny_cutoff, poses_near(*bunny, *bunny, bunny_cutoff, 6, 3), on_bunny);
  const auto block = prox::testing::load_gltf_model("gltf/2CylinderEngine.glb", 9);
  const auto crank = prox::testing::load_gltf_model("gltf/2CylinderEngine.glb", 8);
  ASSERT_TRUE(block && crank);
  const double cad_cutoff = 0.03 * std::max(block->size, crank->size);
  compare(*crank, *block, cad_cutoff, poses_near(*crank, *block, cad_cutoff, 4, 4), on_cad);
  // Two sheets exactly parallel: every candidate's distance ties.
  const auto below = prox::testing::square_sheet(12, 0.1, false), above = prox::testing::square_sheet(9, 0.07, true);
  Pose lifted;
  lifted.translation = Vec3(0.003, 0.002, 0.001);
  compare(*below, *above, 0.005, {lifted}, on_sheets);
  std::printf("[ parallel search ] candidates compared: bunny %d, CAD %d, tied sheets %d\n", on_bunny, on_cad,
              on_sheets);
  EXPECT_GT(on_bunny, 50);
  EXPECT_GT(on_cad, 50);
  EXPECT_GT(on_sheets, 50);
}

TEST(WorkerPool, EveryIndexRunsOnceWhateverThePool) {
  for (unsigned threads : {0u, 1u, 2u, 5u}) {
    WorkerPool pool(threads);
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{1000}}) {
      std::vector<std::atomic<int>> hits(n);
      for (int round = 0; round < 20; ++round) pool.run(n, [&](std::size_t i) { hits[i].fetch_add(1); });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 20) << threads << " threads, index " << i;
    }
  }
}

}  // namespace
}  // namespace prox
