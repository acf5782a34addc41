// Accuracy on deformed shapes (issue 35, part 4): every skinned, morphed or
// animated glTF sample posed at several animation times, its vertices moved
// as the runtime moves them (the rig's pose, welded, Mesh::set_vertices, the
// hierarchy refitted or rebuilt past its limit), against a copy of itself at
// seeded random close poses: the precise method finds exactly the
// brute-force reference's LMDs.
#include "io/gltf.h"
#include "runtime/mesh_rig.h"
#include "support/scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>

namespace prox::testing {
namespace {

struct Rigged {
  std::shared_ptr<const Model> rest;
  std::shared_ptr<const rig::Rig> rig;
};

Rigged load_rigged(const std::string& relative) {
  std::vector<io::GltfMesh> meshes;
  const Status status = io::load_gltf(asset_path(relative), {}, meshes);
  EXPECT_TRUE(status.is_ok()) << status.message();
  if (!status.is_ok() || meshes.size() != 1) return {};
  return {model_from_arrays(meshes[0].positions, meshes[0].indices), meshes[0].rig};
}

// `rest` moved to the rig's current pose, as World::set_vertices moves it.
std::shared_ptr<const Model> deformed(const Model& rest, const runtime::MeshRig& pose) {
  std::vector<Vec3> p;
  pose.welded_positions(rest.mesh, p);
  std::vector<double> xyz;
  for (const Vec3& v : p) xyz.insert(xyz.end(), {v.x, v.y, v.z});
  auto model = std::make_shared<Model>();
  model->mesh = rest.mesh;
  const Status status = model->mesh.set_vertices(xyz.data(), rest.mesh.vertex_count());
  EXPECT_TRUE(status.is_ok()) << status.message();
  model->snch = std::make_unique<Snch>(*rest.snch);
  model->snch->refit(model->mesh);
  if (model->snch->stats().degradation > Snch::kRebuildDegradation)
    model->snch = std::make_unique<Snch>(model->mesh);
  model->size = glm::length(model->mesh.bounds().max - model->mesh.bounds().min);
  model->centre = 0.5 * (model->mesh.bounds().max + model->mesh.bounds().min);
  return model;
}

TEST(RigAccuracy, PreciseMatchesTheReferenceOnDeformedSamples) {
  const char* const files[] = {"gltf/SimpleSkin.gltf",         "gltf/RiggedSimple.glb",
                               "gltf/RiggedFigure.glb",        "gltf/RecursiveSkeletons.glb",
                               "gltf/SimpleMorph.gltf",        "gltf/AnimatedMorphCube.glb",
                               "gltf/MorphPrimitivesTest.glb", "gltf/InterpolationTest.glb"};
  constexpr int kPosesPerShape = 20;
  for (const char* file : files) {
    SCOPED_TRACE(file);
    const Rigged r = load_rigged(file);
    ASSERT_TRUE(r.rest && r.rig);
    // The shapes: each animation at three times, or (MorphPrimitivesTest has
    // none) two settings of its morph weights.
    std::vector<runtime::MeshRig> shapes;
    Status status;
    for (std::size_t a = 0; a < r.rig->animations.size(); ++a)
      for (const double f : {0.3, 0.65, 1.0}) {
        runtime::MeshRig shape(r.rig);
        const rig::Animation& anim = r.rig->animations[a];
        ASSERT_TRUE(
            shape.animate(static_cast<std::int64_t>(a), anim.start + f * (anim.end - anim.start), status));
        shapes.push_back(shape);
      }
    if (shapes.empty())
      for (const double w : {1.0, 0.25}) {
        runtime::MeshRig shape(r.rig);
        const std::vector<double> weights(r.rig->morph_weight_count(), w);
        ASSERT_TRUE(
            shape.set_morph_weights(weights.data(), static_cast<std::int64_t>(weights.size()), status))
            << status.message();
        shapes.push_back(shape);
      }
    Match total;
    int moved = 0;
    PairState state;
    std::mt19937_64 rng(35);
    for (std::size_t s = 0; s < shapes.size(); ++s) {
      const std::shared_ptr<const Model> model = deformed(*r.rest, shapes[s]);
      for (std::uint32_t v = 0; v < model->mesh.vertex_count(); ++v)
        if (model->mesh.vertex(v) != r.rest->mesh.vertex(v)) {
          ++moved;
          break;
        }
      const double cutoff = 0.03 * model->size;
      std::uniform_real_distribution<double> log_gap(std::log(5e-4 * model->size), std::log(cutoff));
      for (int i = 0; i < sampled_poses(kPosesPerShape); ++i) {
        const Pose pose = pose_at_gap(*model, *model, std::exp(log_gap(rng)), rng);
        const PairQuery q = make_query(*model, Pose{}, *model, pose, cutoff);
        ProximityResult ref, fast;
        find_lmds(q, Method::Reference, state, ref);
        find_lmds(q, Method::Precise, state, fast);
        ASSERT_FALSE(ref.lmds.empty()) << "shape " << s << " pose " << i;
        const Match m = match_lmds(ref.lmds, fast.lmds, 1e-9 * model->size);
        total.reference += m.reference, total.found += m.found;
        total.recalled += m.recalled, total.confirmed += m.confirmed;
      }
    }
    std::printf(
        "[ rig accuracy ] %-28s %2zu shapes (%d moved), %4d reference LMDs: recall %.4f precision %.4f\n",
        file, shapes.size(), moved, total.reference, double(total.recalled) / total.reference,
        double(total.confirmed) / std::max(1, total.found));
    EXPECT_GT(moved, 0) << "no shape moved a vertex: the comparison would be of rest poses only";
    EXPECT_EQ(total.recalled, total.reference);
    EXPECT_EQ(total.confirmed, total.found);
  }
}

}  // namespace
}  // namespace prox::testing
