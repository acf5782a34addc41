// The threaded runtime's test scene: the bunny held against a static bunny by
// the scripted device, with faults to inject, and what every run must keep.
// Shared by the threads tests and the living-scene tests.
#pragma once

#include "runtime/scripted_device.h"
#include "runtime/stream_device.h"
#include "runtime/threads.h"
#include "runtime/world.h"
#include "support/marked_threads.h"
#include "support/scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <atomic>
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace prox::runtime {

using prox::testing::load_obj_model;
using prox::testing::make_query;
using Clock = std::chrono::steady_clock;

// The scripted device with faults to inject, as a misbehaving real device
// would produce them.
struct FaultyDevice final : HapticDevice {
  enum Fault { None = 0, NaNPose = 1, NoPose = 2, Teleport = 3 };
  explicit FaultyDevice(HapticDevice& device) : inner(device) {}

  Device device() { return Device::borrowed(*this); }

  bool read_pose(DevicePose* pose) override {
    prox::testing::mark_this_thread(true);
    const bool ok = inner.read_pose(pose);
    switch (fault.load()) {
      case NaNPose:
        pose->position[1] = std::numeric_limits<double>::quiet_NaN();
        break;
      case NoPose:
        return false;
      case Teleport:
        pose->position[0] += 0.2;  // 20 cm in one tick
        break;
      default:
        break;
    }
    return ok;
  }
  void write_wrench(const DeviceWrench& w) override {
    inner.write_wrench(w);
    closest.store(w.closest_distance, std::memory_order_relaxed);
    safety_distance.store(w.safety_distance, std::memory_order_relaxed);
    cutoff.store(w.cutoff, std::memory_order_relaxed);
  }

  HapticDevice& inner;
  std::atomic<int> fault{None};
  // What the last wrench said of the distances.
  std::atomic<double> closest{-1.0}, safety_distance{-1.0}, cutoff{-1.0};
};

inline double length(const Vec3& v) { return glm::length(v); }

inline bool wait_until(const std::function<bool()>& done, double seconds = 60.0) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

class ThreadsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    bunny_ = load_obj_model("bunny.obj");
    ASSERT_TRUE(bunny_);
    // The tool 1 mm from the bunny at rest, in the first of a fixed series of
    // random directions that gives several contacts and an unclipped force
    // (so the force says something about each of them); and 12 mm farther
    // out, beyond the cutoff, where the path starts.
    for (std::uint64_t seed = 11;; ++seed) {
      ASSERT_LT(seed, 60u) << "no direction with several contacts";
      std::mt19937_64 rng(seed);
      near_ = prox::testing::pose_at_gap(*bunny_, *bunny_, 0.001, rng);
      PairState state;
      find_lmds(make_query(*bunny_, Pose{}, *bunny_, near_, world_settings_.cutoff()), Method::Precise, state,
                expected_);
      expected_wrench_ = tool_wrench(world_settings_.force, expected_.lmds, near_.apply(bunny_->centre));
      if (expected_.lmds.size() >= 3 && !expected_wrench_.clipped && length(expected_wrench_.force) > 0.01)
        break;
    }
    const Vec3 out = glm::normalize(expected_wrench_.force);
    far_ = {near_.rotation, near_.translation + 0.012 * out};

    // Every run records its ticks, so the allocation and lock checks below
    // cover the flight recorder too.
    settings_.trace_capacity = 4096;
    world_ = std::make_unique<World>(world_settings_);
    std::vector<double> positions;
    std::vector<std::uint32_t> indices;
    const Mesh& m = bunny_->mesh;
    for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
      positions.insert(positions.end(), {m.vertex(v).x, m.vertex(v).y, m.vertex(v).z});
    for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
      indices.insert(indices.end(), m.indices(t).begin(), m.indices(t).end());
    Status status;
    const Handle mesh = world_->create_mesh({positions.data(), std::uint32_t(positions.size() / 3),
                                             indices.data(), std::uint32_t(indices.size() / 3)},
                                            status);
    ASSERT_TRUE(status) << status.message();
    // The wall has a mesh of its own, which the living-scene tests deform.
    wall_mesh_ = world_->create_mesh({positions.data(), std::uint32_t(positions.size() / 3), indices.data(),
                                      std::uint32_t(indices.size() / 3)},
                                     status);
    ASSERT_TRUE(status) << status.message();
    wall_ = world_->create_body(wall_mesh_, BodyType::Static, Pose{}, Vec3(0.0));
    tool_ = world_->create_body(mesh, BodyType::Tool, far_, bunny_->centre);
    tool_mesh_ = mesh;
  }

  void TearDown() override {
    if (world_) world_->stop_threads();
  }

  // Starts the threads with the tool approaching from far to near in half a
  // second, then held there; returns once the force has settled at rest.
  void start_and_settle(FaultyDevice*& faulty) {
    scripted_ = std::make_unique<ScriptedDevice>(
        std::vector<ScriptedPose>{ScriptedPose::of(far_), ScriptedPose::of(near_)}, 0.5, false);
    faulty_ = std::make_unique<FaultyDevice>(*scripted_);
    faulty = faulty_.get();
    world_->set_device(tool_, faulty_->device());
    Status status;
    ASSERT_TRUE(world_->start_threads(settings_, status)) << status.message();
    ASSERT_TRUE(settled()) << "the threads never reached the deterministic answer at rest";
  }

  bool at_rest_force() const {
    return length(world_->wrench(tool_).force - expected_wrench_.force) <=
           1e-9 * length(expected_wrench_.force);
  }
  bool settled() {
    return wait_until([&] { return scripted_->record().progress >= 1.0 && at_rest_force(); });
  }
  bool faded_out() {
    return wait_until([&] { return length(world_->wrench(tool_).force) == 0.0; }, 30.0);
  }

  // What every run must keep, whatever was injected.
  void expect_safe_output() {
    const ScriptedRecord r = scripted_->record();
    EXPECT_TRUE(r.finite);
    EXPECT_LE(r.max_force, world_settings_.force.max_force + 1e-12);
    EXPECT_LE(r.max_torque, world_settings_.force.max_torque + 1e-12);
    // The gate's rate times its longest step (5 ms), whatever the gaps.
    EXPECT_LE(r.max_force_step, settings_.max_force_rate * 0.005 + 1e-9);
    const HapticCounters c = world_->threads()->haptic_counters();
    EXPECT_EQ(c.torn_snapshots, 0u);
    EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
  }

  WorldSettings world_settings_;
  ThreadSettings settings_;
  std::shared_ptr<const prox::testing::Model> bunny_;
  Pose near_, far_;
  ProximityResult expected_;
  Wrench expected_wrench_;
  std::unique_ptr<World> world_;
  Handle tool_, tool_mesh_, wall_, wall_mesh_;
  std::unique_ptr<ScriptedDevice> scripted_;
  std::unique_ptr<FaultyDevice> faulty_;
};

}  // namespace prox::runtime
