// A scene that lives while the threads run (docs/dynamic-scenes.md): the
// wall deformed under the held tool, bodies made and destroyed beside it. The
// haptic loop must keep its promises through all of it (finite, bounded, no
// allocation), the contacts must follow the new shapes, and a destroyed
// body's contacts must leave the force by a fade, not a step.
#include "runtime/threads_fixture.h"
#include "support/marked_threads.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace prox::runtime {
namespace {

class LivingScene : public ThreadsTest {
 protected:
  // The wall's vertices moved by `offset` (x, y, z per vertex).
  std::vector<double> wall_moved(const Vec3& offset) const {
    std::vector<double> xyz;
    const Mesh& m = bunny_->mesh;
    for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
      const Vec3 p = m.vertex(v) + offset;
      xyz.insert(xyz.end(), {p.x, p.y, p.z});
    }
    return xyz;
  }
  // The contacts and wrench the deterministic method gives with the wall
  // moved by `offset` and the tool held near.
  ProximityResult expected_with_wall_at(const Vec3& offset) const {
    ProximityResult r;
    PairState state;
    find_lmds(make_query(*bunny_, Pose{glm::dmat3(1.0), offset}, *bunny_, near_, world_settings_.cutoff()),
              Method::Precise, state, r);
    return r;
  }
  double closest_contact() const {
    std::vector<Contact> contacts;
    world_->contacts(tool_, contacts);
    double closest = kNoContact;
    for (const Contact& c : contacts) closest = std::min(closest, c.lmd.distance);
    return closest;
  }
  // The recorded ticks of a tool where the safety gate changed a force that
  // was not zero (what a step into the gate looks like).
  int gate_limited_a_force(Handle tool) const {
    std::vector<TraceSample> trace(static_cast<std::size_t>(settings_.trace_capacity));
    const std::size_t n = world_->threads()->trace(tool.index, trace.data(), trace.size());
    int limited = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const bool force = trace[i].force[0] != 0.0 || trace[i].force[1] != 0.0 || trace[i].force[2] != 0.0 ||
                         trace[i - 1].force[0] != 0.0 || trace[i - 1].force[1] != 0.0 || trace[i - 1].force[2] != 0.0;
      if ((trace[i].flags & kTraceClipped) && force) ++limited;
    }
    return limited;
  }
  bool contacts_with(std::uint32_t body) const {
    std::vector<Contact> contacts;
    world_->contacts(tool_, contacts);
    return std::any_of(contacts.begin(), contacts.end(), [&](const Contact& c) { return c.other == body; });
  }
};

// The wall swells 0.3 mm towards the held tool while the global search is
// stalled: local tracking alone carries the contacts onto the new shape, to
// the distance the deterministic method measures there.
TEST_F(LivingScene, ADeformingMeshWritesOverItsRetiredShapes) {
  // Frame after frame a new shape is made in the storage of one retired
  // before it, once no thread holds that: nothing of the size of the mesh's
  // vertices or its hierarchy is allocated (here no thread runs, so the
  // shape retired by a frame is back for the next).
  std::vector<std::vector<double>> frames;
  for (int f = 0; f < 8; ++f) frames.push_back(wall_moved(Vec3(0.0, 0.0, 1e-4 * f)));
  Status status;
  for (int f = 0; f < 2; ++f)
    ASSERT_TRUE(world_->set_vertices(wall_mesh_, frames[f].data(), bunny_->mesh.vertex_count(), status))
        << status.message();
  prox::testing::reset_marked_counts();
  {
    const prox::testing::MarkedScope marked;
    for (int f = 2; f < 8; ++f)
      ASSERT_TRUE(world_->set_vertices(wall_mesh_, frames[f].data(), bunny_->mesh.vertex_count(), status));
  }
  const std::size_t vertices_bytes = bunny_->mesh.vertex_count() * sizeof(Vec3);
  EXPECT_LT(prox::testing::marked_largest_allocation(), vertices_bytes / 8);
  prox::testing::reset_marked_counts();  // the game thread's, not the haptic thread's
  // And the shape is the last frame's, its hierarchy refitted, not rebuilt.
  EXPECT_EQ(world_->mesh(wall_mesh_).vertex(7), bunny_->mesh.vertex(7) + Vec3(0.0, 0.0, 7e-4));
  EXPECT_EQ(world_->snch(wall_mesh_).stats().refits, 8u);
}

TEST_F(LivingScene, ADeformationIsTrackedWithoutAGlobalSearch) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  const Vec3 towards = 0.0003 * glm::normalize(expected_wrench_.force);  // the force pushes the tool away
  const ProximityResult expected = expected_with_wall_at(towards);
  ASSERT_FALSE(expected.lmds.empty());
  double closest = kNoContact;
  for (const LmdPair& p : expected.lmds) closest = std::min(closest, p.distance);
  ASSERT_LT(closest, closest_contact() - 1e-4) << "the move must bring the wall closer";

  Threads& threads = *world_->threads();
  threads.stall(Role::Global, true);
  const std::uint64_t searches = threads.loop_summary(Role::Global).updates;
  const std::vector<double> xyz = wall_moved(towards);
  Status status;
  ASSERT_TRUE(world_->set_vertices(wall_mesh_, xyz.data(), bunny_->mesh.vertex_count(), status))
      << status.message();
  EXPECT_TRUE(wait_until([&] { return std::abs(closest_contact() - closest) <= 1e-9 * closest; }))
      << "closest contact " << closest_contact() << " m, the deformed wall's " << closest << " m";
  EXPECT_LE(threads.loop_summary(Role::Global).updates, searches + 1) << "the global search ran";
  // Released, the global search agrees: the same contacts as the
  // deterministic method on the deformed wall, and its force.
  threads.stall(Role::Global, false);
  const Wrench w = tool_wrench(world_settings_.force, expected.lmds, near_.apply(bunny_->centre));
  EXPECT_TRUE(wait_until([&] {
    std::vector<Contact> contacts;
    world_->contacts(tool_, contacts);
    return contacts.size() == expected.lmds.size() &&
           length(world_->wrench(tool_).force - w.force) <= 1e-9 * length(w.force);
  })) << "the threads never reached the deformed wall's force";
  expect_safe_output();
}

// The held tool itself swells 0.3 mm towards the wall (in its own frame)
// while the global search is stalled: its contacts are tracked on its new
// shape, to the distance the deterministic method measures there.
TEST_F(LivingScene, AHeldToolDeformsUnderTheHand) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  const Vec3 towards_wall = -0.0003 * glm::normalize(expected_wrench_.force);
  const Vec3 local = glm::transpose(near_.rotation) * towards_wall;
  // Moving every vertex by `local` in the tool's frame is the tool moved by
  // `towards_wall` in the world's.
  ProximityResult expected;
  PairState state;
  const Pose moved{near_.rotation, near_.translation + towards_wall};
  find_lmds(make_query(*bunny_, Pose{}, *bunny_, moved, world_settings_.cutoff()), Method::Precise, state, expected);
  ASSERT_FALSE(expected.lmds.empty());
  double closest = kNoContact;
  for (const LmdPair& p : expected.lmds) closest = std::min(closest, p.distance);
  ASSERT_LT(closest, closest_contact() - 1e-4);

  world_->threads()->stall(Role::Global, true);
  const std::vector<double> xyz = wall_moved(local);  // the bunny's vertices, moved
  Status status;
  ASSERT_TRUE(world_->set_vertices(tool_mesh_, xyz.data(), bunny_->mesh.vertex_count(), status))
      << status.message();
  EXPECT_TRUE(wait_until([&] { return std::abs(closest_contact() - closest) <= 1e-9 * closest; }))
      << "closest contact " << closest_contact() << " m, the deformed tool's " << closest << " m";
  world_->threads()->stall(Role::Global, false);
  const Wrench w = tool_wrench(world_settings_.force, expected.lmds, moved.apply(bunny_->centre));
  EXPECT_TRUE(wait_until([&] {
    return length(world_->wrench(tool_).force - w.force) <= 1e-9 * length(w.force);
  })) << "the threads never reached the deformed tool's force";
  expect_safe_output();
}

// The wall destroyed under the held tool: its contacts leave, and the force
// fades to zero without the safety gate having to limit it. Made again, it
// is found and the force returns.
TEST_F(LivingScene, ADestroyedBodyFadesOutAndANewOneIsFound) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  const std::uint64_t limited = world_->threads()->haptic_counters().limited_ticks;
  world_->destroy_body(wall_);
  EXPECT_TRUE(wait_until([&] { return !contacts_with(wall_.index); })) << "the destroyed wall's contacts stayed";
  EXPECT_TRUE(faded_out());
  EXPECT_EQ(world_->threads()->haptic_counters().limited_ticks, limited)
      << "the force stepped: the gate had to limit it";
  EXPECT_EQ(length(scripted_->record().last_force), 0.0);

  wall_ = world_->create_body(wall_mesh_, BodyType::Static, Pose{}, Vec3(0.0));
  EXPECT_TRUE(wait_until([&] { return contacts_with(wall_.index) && at_rest_force(); }))
      << "the new wall was never felt";
  EXPECT_EQ(world_->threads()->haptic_counters().limited_ticks, limited);
  expect_safe_output();
}

// Storms beside a held tool: bodies made and destroyed in and out of range,
// and the wall deformed, as fast as the game thread can. The haptic loop
// stays safe and allocation-free, and the scene, back where it started,
// gives the force it gave before.
TEST_F(LivingScene, StormsOfChangesLeaveTheLoopSafeAndTheAnswerRight) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // 4 mm cubes around the tool, 0 to 10 mm beyond its bounding sphere:
  // some in its cutoff, some crossing it, some far.
  const double corners[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  std::vector<double> cube;
  for (const double c : corners) cube.push_back(0.004 * c);
  const std::vector<std::uint32_t> cube_indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  Status made_cube;
  const Handle cube_mesh = world_->create_mesh({cube.data(), 8, cube_indices.data(), 12}, made_cube);
  ASSERT_TRUE(made_cube) << made_cube.message();
  const Vec3 centre = near_.apply(bunny_->centre);
  double radius = 0.0;
  for (std::uint32_t v = 0; v < bunny_->mesh.vertex_count(); ++v)
    radius = std::max(radius, length(bunny_->mesh.vertex(v) - bunny_->centre));
  std::vector<Handle> made;
  const std::uint64_t local_start = world_->threads()->loop_summary(Role::Local).updates;
  for (int i = 0; i < 200; ++i) {
    const Vec3 direction = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-9));
    const Pose pose{glm::dmat3(1.0), centre + (radius + 0.005 + 0.005 * u(rng)) * direction};
    made.push_back(world_->create_body(i % 2 ? cube_mesh : wall_mesh_, BodyType::Static,
                                       i % 2 ? pose : Pose{glm::dmat3(1.0), Vec3(1.0, 0.0, 0.0)}, Vec3(0.0)));
    if (made.size() > 4) {
      world_->destroy_body(made.front());
      made.erase(made.begin());
    }
    // The wall's 70k triangles are refitted on this thread: every 8th turn.
    if (i % 8 == 0) {
      const std::vector<double> xyz = wall_moved(0.0002 * Vec3(u(rng), u(rng), u(rng)));
      Status status;
      ASSERT_TRUE(world_->set_vertices(wall_mesh_, xyz.data(), bunny_->mesh.vertex_count(), status));
    }
    // Give the tracking threads a turn now and then, so that the storm
    // meets them mid-iteration rather than only between runs.
    if (i % 16 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_GT(world_->threads()->loop_summary(Role::Local).updates, local_start) << "local tracking never ran";
  for (const Handle h : made) world_->destroy_body(h);
  const std::vector<double> rest = wall_moved(Vec3(0.0));
  Status status;
  ASSERT_TRUE(world_->set_vertices(wall_mesh_, rest.data(), bunny_->mesh.vertex_count(), status));
  EXPECT_TRUE(wait_until([&] { return at_rest_force(); })) << "the restored scene's force never came back";
  expect_safe_output();
}

// Tools come and go while the threads run. The held tool destroyed in
// contact: its device's wrench fades to an exact zero before the call
// returns, and the device is called no more. A new tool made in its place,
// given a device of its own: driven, its contacts found, its force faded in.
// Its device swapped for another: the first one faded out and let go of.
TEST_F(LivingScene, ToolsComeAndGoWithTheirDevicesFadedInAndOut) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  world_->destroy_body(tool_);
  const ScriptedRecord gone = scripted_->record();
  EXPECT_EQ(length(gone.last_force), 0.0) << "the device was left with a force";
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(scripted_->record().reads, gone.reads) << "the destroyed tool's device was still read";
  EXPECT_EQ(scripted_->record().writes, gone.writes) << "the destroyed tool's device was still written";

  // A bunny tool made again where the first one was held, on a device of its own.
  ScriptedDevice held({ScriptedPose::of(near_)}, 1.0, false);
  FaultyDevice second(held);
  const Handle tool = world_->create_body(wall_mesh_, BodyType::Tool, far_, bunny_->centre);
  world_->set_device(tool, Device::borrowed(second));
  EXPECT_TRUE(wait_until([&] {
    return length(world_->wrench(tool).force - expected_wrench_.force) <= 1e-9 * length(expected_wrench_.force);
  })) << "the new tool never reached the held tool's force";
  EXPECT_GT(held.record().reads, 0u);
  // The new tool's first tick has no contacts yet (the gate holds it at 0,
  // flagged); from there on the force fades in, the gate never limiting it.
  EXPECT_EQ(gate_limited_a_force(tool), 0) << "the new tool's force stepped";

  // Its device swapped for a third, held at the same pose.
  ScriptedDevice third_device({ScriptedPose::of(near_)}, 1.0, false);
  FaultyDevice third(third_device);
  world_->set_device(tool, Device::borrowed(third));
  const ScriptedRecord swapped = held.record();
  EXPECT_EQ(length(swapped.last_force), 0.0);
  EXPECT_TRUE(wait_until([&] {
    return length(world_->wrench(tool).force - expected_wrench_.force) <= 1e-9 * length(expected_wrench_.force);
  })) << "the swapped device never got the force back";
  EXPECT_EQ(held.record().writes, swapped.writes) << "the swapped-out device was still written";
  EXPECT_GT(third_device.record().writes, 0u);
  EXPECT_EQ(gate_limited_a_force(tool), 0) << "the swapped tool's force stepped";
  EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
  EXPECT_EQ(world_->threads()->haptic_counters().torn_snapshots, 0u);
  world_->stop_threads();
  EXPECT_EQ(length(third_device.record().last_force), 0.0);
}

}  // namespace
}  // namespace prox::runtime
