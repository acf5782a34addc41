// The constrained tool on the threads (docs/coupling.md): the scripted
// device pushes the bunny through the other bunny and back in real time;
// the game thread samples the proxy as a renderer would. Its own program:
// it counts allocations on the haptic thread (support/marked_threads.h).
#include "coupling_scenes.h"

#include "coupling/clearance.h"
#include "runtime/scripted_device.h"
#include "runtime/threads.h"
#include "support/marked_threads.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <new>
#include <thread>

namespace prox {
namespace {

using namespace coupling_scenes;

// The scripted device, marking the thread that reads it (the haptic one).
struct MarkingDevice final : runtime::HapticDevice {
  explicit MarkingDevice(std::shared_ptr<runtime::HapticDevice> device) : inner(std::move(device)) {}
  bool read_pose(runtime::DevicePose* pose) override {
    prox::testing::mark_this_thread(true);
    return inner->read_pose(pose);
  }
  void write_wrench(const runtime::DeviceWrench& w) override { inner->write_wrench(w); }
  std::shared_ptr<runtime::HapticDevice> inner;
};

TEST(ConstrainedToolThreads, BunnyThroughAndBackStaysOutside) {
  std::string error;
  const Scene scene = make_scene("bunny", error);
  ASSERT_EQ(error, "");
  const Vec3 out(1.0, 0.0, 0.0);
  const Vec3 near = clear_offset(scene, out, 0.005), far = clear_offset(scene, -out, 0.005);
  Pose start;
  start.translation = near;
  Built b = build(scene, start, true, error);
  ASSERT_EQ(error, "");
  runtime::World& w = *b.world;
  // Through and back at 0.5 m/s, then held at the start.
  std::vector<runtime::ScriptedPose> poses;
  for (const Vec3& p : {near, far, near}) poses.push_back({{p.x, p.y, p.z}, {1.0, 0.0, 0.0, 0.0}});
  const double seconds_per_pose = glm::length(far - near) / 0.5;
  auto scripted = std::make_shared<runtime::ScriptedDevice>(poses, seconds_per_pose, false);
  w.set_device(b.tool, runtime::Device{std::make_shared<MarkingDevice>(scripted)});

  runtime::ThreadSettings settings;
  Status status;
  ASSERT_TRUE(w.start_threads(settings, status)) << status.message();
  const double safety = scene.settings.force.safety_distance;
  coupling::NodeStack stack;
  int samples = 0, too_close = 0;
  double max_offset = 0.0;
  const auto begin = std::chrono::steady_clock::now();
  const auto end = begin + std::chrono::duration<double>(2.0 * seconds_per_pose + 1.5);
  while (std::chrono::steady_clock::now() < end) {
    const Pose proxy = w.proxy_pose(b.tool);
    const PairQuery q{&w.mesh(b.obstacle_mesh),
                      &w.snch(b.obstacle_mesh),
                      Pose{},
                      &w.mesh(b.tool_mesh),
                      &w.snch(b.tool_mesh),
                      proxy,
                      0.0};
    too_close += coupling::closer_than(q, safety * (1.0 - 1e-6), stack);
    max_offset = std::max(max_offset, glm::length(proxy.translation - w.current_pose(b.tool).translation));
    ++samples;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  w.stop_threads();

  EXPECT_GT(samples, 50);
  EXPECT_EQ(too_close, 0) << "of " << samples << " samples";
  EXPECT_GT(max_offset, 0.02) << "the device went through, the proxy did not";
  // Once the path is clear the proxy is back on the device pose.
  const Pose device = w.current_pose(b.tool), proxy = w.proxy_pose(b.tool);
  EXPECT_LT(glm::length(proxy.translation - device.translation), 1e-9);
  const runtime::ScriptedRecord record = scripted->record();
  EXPECT_TRUE(record.finite);
  EXPECT_LE(record.max_force, scene.settings.force.max_force * (1.0 + 1e-12));
  EXPECT_GT(record.max_force, 1.0);  // the coupling pulled the hand back out
  EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
}

}  // namespace
}  // namespace prox
