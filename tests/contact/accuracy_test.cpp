// The engine against the brute-force reference: bunny against bunny at 200
// seeded random close poses.
#include "support/scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>

namespace prox::testing {
namespace {

constexpr double kCutoff = 0.005;  // 5 mm on a 0.155 m bunny
// The two largest parts of 2CylinderEngine.glb (PerNode order): "body_2"
// and "body_3", about 11k triangles each, open, with long thin triangles.
constexpr int kEngineBlock = 9, kEngineCase = 10;
constexpr int kPoses = 200;

std::shared_ptr<const Model> bunny() {
  static const std::shared_ptr<const Model> model = load_obj_model("bunny.obj");
  return model;
}

// Gaps from a tenth of a millimetre to the cutoff, log-uniform.
double random_gap(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(std::log(1e-4), std::log(kCutoff));
  return std::exp(u(rng));
}

std::vector<LmdPair> within(const std::vector<LmdPair>& lmds, double cutoff) {
  std::vector<LmdPair> out;
  for (const LmdPair& p : lmds)
    if (p.distance <= cutoff) out.push_back(p);
  return out;
}

TEST(Accuracy, PreciseMatchesTheReferenceOnBunnyPairs) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  const double tolerance = 1e-9 * model->size;
  std::mt19937_64 rng(1);
  PairState state;
  Match precise, original, original_loose;
  long candidates = 0;
  int poses_with_contacts = 0;
  double precise_error = 0.0, original_error = 0.0;  // of the minimum distance, over the model size
  for (int i = 0; i < sampled_poses(kPoses); ++i) {
    const double gap = random_gap(rng);
    const Pose pose = pose_at_gap(*model, *model, gap, rng);
    const PairQuery q = make_query(*model, Pose{}, *model, pose, kCutoff);
    ProximityResult ref, fast, base;
    find_lmds(q, Method::Reference, state, ref);
    find_lmds(q, Method::Precise, state, fast);
    find_lmds(q, Method::Original, state, base);

    // The pose generator put the meshes `gap` apart, so the reference's
    // closest LMD is that far: two exact computations agree.
    ASSERT_FALSE(ref.lmds.empty()) << "pose " << i;
    EXPECT_NEAR(ref.min_distance, gap, 1e-9 * model->size) << "pose " << i;
    EXPECT_NEAR(fast.min_distance, ref.min_distance, 1e-9 * model->size) << "pose " << i;
    EXPECT_GE(fast.candidates, fast.lmds.size());
    EXPECT_EQ(fast.global.cut_node_pairs, 0u) << "pose " << i << ": past the default leaf budget";
    precise_error = std::max(precise_error, std::abs(fast.min_distance - ref.min_distance) / model->size);
    if (base.min_distance >= 0.0)
      original_error = std::max(original_error, std::abs(base.min_distance - ref.min_distance) / model->size);
    candidates += fast.candidates;
    ++poses_with_contacts;

    const Match m = match_lmds(ref.lmds, fast.lmds, tolerance);
    precise.reference += m.reference, precise.found += m.found;
    precise.recalled += m.recalled, precise.confirmed += m.confirmed;
    // The baseline's points are feature points, not closest points: match
    // them exactly and within 2 mm, and record both.
    const Match o = match_lmds(ref.lmds, base.lmds, tolerance);
    const Match ol = match_lmds(ref.lmds, base.lmds, 0.002);
    original.reference += o.reference, original.found += o.found;
    original.recalled += o.recalled, original.confirmed += o.confirmed;
    original_loose.reference += ol.reference, original_loose.found += ol.found;
    original_loose.recalled += ol.recalled, original_loose.confirmed += ol.confirmed;
  }
  const double recall = double(precise.recalled) / precise.reference;
  const double precision = double(precise.confirmed) / precise.found;
  std::printf("[ accuracy ] %d poses, %d reference LMDs, %ld precise candidates before reduction\n",
              poses_with_contacts, precise.reference, candidates);
  std::printf(
      "[ accuracy ] precise:  recall %.4f precision %.4f (%d found), max min-distance error %.2e of the "
      "size\n",
      recall, precision, precise.found, precise_error);
  std::printf("[ accuracy ] original: max min-distance error %.2e of the size\n", original_error);
  std::printf(
      "[ accuracy ] original: recall %.4f precision %.4f (%d found); within 2 mm: recall %.4f precision "
      "%.4f\n",
      double(original.recalled) / original.reference,
      double(original.confirmed) / std::max(1, original.found), original.found,
      double(original_loose.recalled) / original_loose.reference,
      double(original_loose.confirmed) / std::max(1, original_loose.found));
  EXPECT_GE(recall, 0.995);
  EXPECT_GE(precision, 0.995);
  RecordProperty("precise_recall", std::to_string(recall));
  RecordProperty("precise_precision", std::to_string(precision));
}

// Real glTF models, open and closed, smooth and CAD: the precise method
// against the reference at random close poses, with the cutoff and the gaps
// scaled to each model.
TEST(Accuracy, PreciseMatchesTheReferenceOnGltfModels) {
  struct Pair {
    const char* name;
    std::shared_ptr<const Model> a, b;
  };
  const std::vector<Pair> pairs = {
      {"Duck", load_gltf_model("gltf/Duck.glb"), load_gltf_model("gltf/Duck.glb")},
      {"Suzanne", load_gltf_model("gltf/Suzanne/Suzanne.gltf"), load_gltf_model("gltf/Suzanne/Suzanne.gltf")},
      {"DamagedHelmet", load_gltf_model("gltf/DamagedHelmet.glb"), load_gltf_model("gltf/Duck.glb")},
      {"2CylinderEngine parts", load_gltf_model("gltf/2CylinderEngine.glb", kEngineBlock),
       load_gltf_model("gltf/2CylinderEngine.glb", kEngineCase)},
  };
  PairState state;
  for (const Pair& pair : pairs) {
    ASSERT_TRUE(pair.a && pair.b) << pair.name;
    const double size = std::max(pair.a->size, pair.b->size);
    const double cutoff = 0.03 * size;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> log_gap(std::log(5e-4 * size), std::log(cutoff));
    Match total, original;
    double error = 0.0;
    for (int i = 0; i < sampled_poses(50); ++i) {
      const double gap = std::exp(log_gap(rng));
      const Pose pose = pose_at_gap(*pair.a, *pair.b, gap, rng);
      const PairQuery q = make_query(*pair.a, Pose{}, *pair.b, pose, cutoff);
      ProximityResult ref, fast, base;
      find_lmds(q, Method::Reference, state, ref);
      find_lmds(q, Method::Precise, state, fast);
      find_lmds(q, Method::Original, state, base);
      ASSERT_FALSE(ref.lmds.empty()) << pair.name << " pose " << i;
      EXPECT_EQ(fast.global.cut_node_pairs, 0u)
          << pair.name << " pose " << i << ": past the default leaf budget";
      error = std::max(error, std::abs(fast.min_distance - ref.min_distance) / size);
      const Match m = match_lmds(ref.lmds, fast.lmds, 1e-9 * size);
      total.reference += m.reference, total.found += m.found;
      total.recalled += m.recalled, total.confirmed += m.confirmed;
      // As for the bunny (2 mm there): the original's points within about 1.3% of the model size.
      const Match o = match_lmds(ref.lmds, base.lmds, 0.013 * size);
      original.reference += o.reference, original.found += o.found;
      original.recalled += o.recalled, original.confirmed += o.confirmed;
    }
    const double recall = double(total.recalled) / total.reference;
    const double precision = double(total.confirmed) / total.found;
    std::printf(
        "[ accuracy ] %-22s %5u/%5u triangles, %4d reference LMDs: precise recall %.4f precision %.4f, "
        "min-distance error %.1e of the size; original (points within 1.3%% of the size) recall %.4f "
        "precision %.4f\n",
        pair.name, pair.a->mesh.triangle_count(), pair.b->mesh.triangle_count(), total.reference, recall,
        precision, error, double(original.recalled) / original.reference,
        double(original.confirmed) / std::max(1, original.found));
    EXPECT_GE(recall, 0.995) << pair.name;
    EXPECT_GE(precision, 0.995) << pair.name;
    EXPECT_LE(error, 1e-9) << pair.name;
  }
}

// The finding of docs/engine.md: the paper's visibility pre-test, projecting
// along averaged vertex normals, drops true contacts at sharp CAD edges; the
// sound pre-test keeps every one among the candidates.
TEST(Accuracy, PapersVisibilityTestLosesContactsAtSharpFeatures) {
  const auto a = load_gltf_model("gltf/2CylinderEngine.glb", kEngineBlock);
  const auto b = load_gltf_model("gltf/2CylinderEngine.glb", kEngineCase);
  ASSERT_TRUE(a && b);
  const double size = std::max(a->size, b->size), cutoff = 0.03 * size;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> log_gap(std::log(5e-4 * size), std::log(cutoff));
  PairState state;
  int reference = 0, sound = 0, paper = 0;
  for (int i = 0; i < 8; ++i) {
    const Pose pose = pose_at_gap(*a, *b, std::exp(log_gap(rng)), rng);
    PairQuery q = make_query(*a, Pose{}, *b, pose, cutoff);
    ProximityResult ref;
    find_lmds(q, Method::Reference, state, ref);
    reference += static_cast<int>(ref.lmds.size());
    for (const auto mode : {PairQuery::Visibility::Sound, PairQuery::Visibility::Paper}) {
      q.visibility = mode;
      std::vector<LmdPair> candidates;
      GlobalSearchStats stats;
      global_search_precise(q, candidates, stats);
      (mode == PairQuery::Visibility::Sound ? sound : paper) +=
          match_lmds(ref.lmds, candidates, 1e-9 * size).recalled;
    }
  }
  std::printf("[ visibility ] CAD parts, %d reference LMDs: candidates recall %.3f (sound), %.3f (paper's)\n",
              reference, double(sound) / reference, double(paper) / reference);
  ASSERT_GT(reference, 50);
  EXPECT_EQ(sound, reference);
  EXPECT_LT(paper, 0.9 * reference);
}

// Tracking is measured on LMDs, not patches: a seed carries its patch
// along, but which LMD of a moved patch is its closest is the next global
// search's to say.
PairQuery unmerged(PairQuery q) {
  q.patches.radius_over_cutoff = 0.0;
  return q;
}

TEST(Accuracy, LocalTrackingFollowsASmallMotion) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  const double tolerance = 1e-9 * model->size;
  // Tracked sets carry a margin beyond the cutoff, as the runtime does, so
  // that a pair entering the cutoff is already being tracked.
  const double margin = 0.001;
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairState state;
  Match total;
  int births = 0;
  for (int i = 0; i < 100; ++i) {
    const double gap = 0.0005 + random_gap(rng);
    const Pose before = pose_at_gap(*model, *model, gap, rng);
    ProximityResult start;
    find_lmds(unmerged(make_query(*model, Pose{}, *model, before, kCutoff + margin)), Method::Precise, state,
              start);

    // One local update's worth of motion: 10 um and 0.01 degree about b's
    // centre, a hand moving at 1 cm/s seen by a 1 kHz tracker.
    const Vec3 axis = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3));
    const Pose turn{glm::mat3_cast(glm::angleAxis(0.01 * kPi / 180.0, axis)), Vec3(0.0)};
    const Vec3 c = before.apply(model->centre);
    Pose after = Pose{glm::dmat3(1.0), c + 1e-5 * glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3))} *
                 turn * Pose{glm::dmat3(1.0), -c} * before;
    const PairQuery q = unmerged(make_query(*model, Pose{}, *model, after, kCutoff + margin));
    LocalTrackingStats stats;
    std::vector<LmdPair> tracked = start.lmds;
    state.precise.update(q, tracked, stats);

    ProximityResult ref;
    find_lmds(unmerged(make_query(*model, Pose{}, *model, after, kCutoff)), Method::Reference, state, ref);
    const Match m = match_lmds(ref.lmds, within(tracked, kCutoff), tolerance);
    total.reference += m.reference, total.found += m.found;
    total.recalled += m.recalled, total.confirmed += m.confirmed;
    // Tracking cannot create an LMD: a new local minimum (a "birth") is the
    // global search's to find, and the next one must.
    if (m.recalled < m.reference) {
      ProximityResult fresh;
      find_lmds(unmerged(make_query(*model, Pose{}, *model, after, kCutoff)), Method::Precise, state, fresh);
      EXPECT_EQ(match_lmds(ref.lmds, fresh.lmds, tolerance).recalled, m.reference) << "pose " << i;
      births += m.reference - m.recalled;
    }
  }
  const double recall = double(total.recalled) / total.reference;
  const double precision = double(total.confirmed) / total.found;
  std::printf("[ tracking ] %d reference LMDs after the motion: recall %.4f precision %.4f, %d births\n",
              total.reference, recall, precision, births);
  EXPECT_GT(total.reference, 100);
  EXPECT_GE(recall, 0.995);
  EXPECT_GE(precision, 0.995);
}

// The cache is emptied by a new stamp per update, not by clearing it; at
// the stamps' wrap-around it is cleared for real. Either way no update sees
// an earlier one's results: the same updates give the same answer as a
// tracker whose stamps are far from wrapping.
TEST(Accuracy, LocalTrackingCacheForgetsEveryEarlierUpdateAcrossItsStampWrap) {
  const auto model = bunny();
  ASSERT_TRUE(model);
  std::mt19937_64 rng(5);
  PairState state;
  LocalTracker fresh, wrapping;
  wrapping.set_stamp_for_testing(0xFFFFFFFEu);  // the updates below use ...FF, then 1, 2, ...
  for (int i = 0; i < 6; ++i) {
    const Pose pose = pose_at_gap(*model, *model, 0.0005 + random_gap(rng), rng);
    ProximityResult start;
    find_lmds(unmerged(make_query(*model, Pose{}, *model, pose, kCutoff)), Method::Precise, state, start);
    ASSERT_FALSE(start.lmds.empty());
    // Tracked a little way on, and back: the second update revisits the
    // first one's triangle pairs at other poses.
    const Pose moved{pose.rotation, pose.translation + Vec3(2e-5, -1e-5, 1e-5)};
    for (const Pose& at : {moved, pose}) {
      const PairQuery q = unmerged(make_query(*model, Pose{}, *model, at, kCutoff));
      std::vector<LmdPair> a = start.lmds, b = start.lmds;
      LocalTrackingStats sa, sb;
      fresh.update(q, a, sa);
      wrapping.update(q, b, sb);
      ASSERT_EQ(a.size(), b.size()) << "pose " << i;
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].tri_a, b[k].tri_a);
        EXPECT_EQ(a[k].tri_b, b[k].tri_b);
        EXPECT_EQ(a[k].distance, b[k].distance);
      }
      EXPECT_EQ(sa.distance_evaluations, sb.distance_evaluations);
      EXPECT_EQ(sa.cache_hits, sb.cache_hits);
    }
  }
}

}  // namespace
}  // namespace prox::testing
