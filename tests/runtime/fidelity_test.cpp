// What the hand feels, on the real threads (docs/haptic-fidelity.md): two
// 10 cm cubes, a device of the test's own moving the tool, every tick read
// back from the flight recorder. Each test closes its loop on the recorded
// ticks, never on elapsed time. Free air renders exactly nothing, in both
// tool modes and from the first tick; a constrained proxy away from its
// device at the start joins it without a pulse; the constrained proxy is
// the device pose itself in free air at every tick; a free tool's contacts
// born inside the cutoff fade in. Its own program with the threads tests'
// allocation count (support/marked_threads.h).
#include "runtime/threads.h"
#include "runtime/world.h"
#include "support/marked_threads.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

namespace prox::runtime {
namespace {

bool wait_for(const std::function<bool()>& done, double seconds = 60.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

// A device moving the tool along x by the haptic thread's own tick count:
// `x0` and then `speed` m per tick (a hand at speed * 1000 m/s at 1 kHz).
struct SlidingDevice final : HapticDevice {
  std::atomic<double> x0{0.0};
  std::atomic<double> per_tick{0.0};
  std::atomic<long> reads{0};
  bool read_pose(DevicePose* pose) override {
    prox::testing::mark_this_thread(true);
    const long n = reads.fetch_add(1);
    *pose = {{x0.load() + per_tick.load() * double(n), 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
    return true;
  }
};

class Fidelity : public ::testing::Test {
 protected:
  // The wall cube at the origin, the tool cube created at x = created
  // (its face at x - 0.1 from the wall's), soft force settings (10 mm
  // cutoff).
  void make_world(double created, coupling::ToolMode mode) {
    WorldSettings ws;
    ws.force = soft_force_settings();
    ws.force.cutoff = 0.01;
    world_ = std::make_unique<World>(ws);
    const double c[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    for (double v : c) positions_.push_back(0.1 * v);
    Status status;
    const Handle mesh = world_->create_mesh({positions_.data(), 8, indices_.data(), 12}, status);
    ASSERT_TRUE(status) << status.message();
    world_->create_body(mesh, BodyType::Static, Pose{}, Vec3(0.0));
    Pose at;
    at.translation = Vec3(created, 0.0, 0.0);
    ToolSettings tool;
    tool.mode = mode;
    tool_ = world_->create_body(mesh, BodyType::Tool, at, Vec3(0.05), tool);
    world_->set_device(tool_, Device::borrowed(device_));
  }
  void start(ThreadSettings settings = {}) {
    settings.trace_capacity = 1 << 16;
    Status status;
    ASSERT_TRUE(world_->start_threads(settings, status)) << status.message();
  }
  std::vector<TraceSample> trace() const {
    std::vector<TraceSample> out(1 << 16);
    out.resize(world_->threads()->trace(tool_.index, out.data(), out.size()));
    return out;
  }
  std::size_t ticks() const { return trace().size(); }
  void TearDown() override {
    if (world_) world_->stop_threads();
    EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread allocated";
  }
  static double force(const TraceSample& s) { return std::sqrt(s.force[0] * s.force[0] + s.force[1] * s.force[1] +
                                                               s.force[2] * s.force[2]); }

  std::vector<double> positions_;
  std::vector<std::uint32_t> indices_ = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                         2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  SlidingDevice device_;
  std::unique_ptr<World> world_;
  Handle tool_;
};

// A constrained tool created 34 mm from where its device starts, nothing
// within the cutoff of either, the hand moving through free air at 50 mm/s:
// every tick renders exactly 0 N and 0 N m, the first ones included, and
// the proxy is the device pose itself once it has joined it. (Before the
// proxy moved at the haptic rate, the start was a 3 N pulse and free air a
// drag of speed times the local thread's lag.)
TEST_F(Fidelity, ConstrainedToolInFreeAirRendersNothingFromTheFirstTick) {
  ASSERT_NO_FATAL_FAILURE(make_world(0.3 + 0.034, coupling::ToolMode::Constrained));
  device_.x0 = 0.3;            // 200 mm from the wall's face: far beyond the cutoff
  device_.per_tick = 0.00005;  // 50 mm/s at 1 kHz, away from the wall
  ASSERT_NO_FATAL_FAILURE(start());
  ASSERT_TRUE(wait_for([&] { return ticks() >= 600; }));
  const std::vector<TraceSample> t = trace();
  std::size_t joined = t.size();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const TraceSample& s = t[i];
    ASSERT_EQ(s.force[0], 0.0) << "tick " << s.tick;
    ASSERT_EQ(s.force[1], 0.0) << "tick " << s.tick;
    ASSERT_EQ(s.force[2], 0.0) << "tick " << s.tick;
    ASSERT_EQ(s.torque[0] + s.torque[1] + s.torque[2], 0.0) << "tick " << s.tick;
    const bool on_device = std::memcmp(s.device, s.proxy, sizeof s.device) == 0;
    if (on_device && joined == t.size()) joined = i;
    if (joined < t.size()) {
      ASSERT_TRUE(on_device) << "tick " << s.tick << ": the proxy left the device pose in free air";
    }
  }
  EXPECT_LT(joined, t.size()) << "the proxy never joined the device";
}

// The same for a free tool (whose force is the contacts' own).
TEST_F(Fidelity, FreeToolInFreeAirRendersNothing) {
  ASSERT_NO_FATAL_FAILURE(make_world(0.3, coupling::ToolMode::Free));
  device_.x0 = 0.3;
  device_.per_tick = 0.00005;
  ASSERT_NO_FATAL_FAILURE(start());
  ASSERT_TRUE(wait_for([&] { return ticks() >= 300; }));
  for (const TraceSample& s : trace()) ASSERT_EQ(force(s), 0.0) << "tick " << s.tick;
}

// A constrained tool pushed 3 mm into the wall: the proxy it renders at the
// haptic rate stays outside (its x at least the safety distance from the
// face, the cubes' faces being parallel), the force pushes the hand out and
// is what the spring to the ideal proxy gives.
TEST_F(Fidelity, ConstrainedToolPressedIntoTheWallIsHeldOutside) {
  ASSERT_NO_FATAL_FAILURE(make_world(0.104, coupling::ToolMode::Constrained));
  device_.x0 = 0.104;
  device_.per_tick = -0.000005;  // 5 mm/s towards the wall, for 7 mm: 3 mm into it
  ASSERT_NO_FATAL_FAILURE(start());
  ASSERT_TRUE(wait_for([&] { return ticks() >= 1400; }));
  device_.per_tick = 0.0;
  device_.x0 = 0.097 - 0.0;  // held 3 mm inside
  device_.reads = 0;
  ASSERT_TRUE(wait_for([&] {
    const std::vector<TraceSample> t = trace();
    return !t.empty() && t.back().device[0] == 0.097 && force(t.back()) > 2.0;
  }));
  const double safety = soft_force_settings().safety_distance;
  double largest = 0.0;
  for (const TraceSample& s : trace()) {
    ASSERT_GE(s.proxy[0] - 0.1, safety * (1.0 - 1e-9)) << "tick " << s.tick << ": the proxy went inside";
    largest = std::max(largest, s.force[0]);
  }
  EXPECT_GT(largest, 2.0) << "the spring pulls the hand out of the wall";
}

// A free tool far from everything, its device jumping to 2 mm from the wall
// in one tick: the contacts arrive with the next searches, well inside the
// 10 mm cutoff, a force of over 1 N at once. It fades in: no tick's change,
// per millisecond of it, comes near the safety gate's 0.3 N, and it settles
// on the contacts' force.
TEST_F(Fidelity, ContactsBornInsideTheCutoffFadeIn) {
  ASSERT_NO_FATAL_FAILURE(make_world(0.102, coupling::ToolMode::Free));
  world_->step();  // what the contacts give at rest
  const double expected = glm::length(world_->wrench(tool_).force);
  ASSERT_GT(expected, 1.0);
  device_.x0 = 0.3;
  ASSERT_NO_FATAL_FAILURE(start());
  ASSERT_TRUE(wait_for([&] { return ticks() >= 200; }));
  device_.x0 = 0.102;
  ASSERT_TRUE(wait_for([&] {
    const std::vector<TraceSample> t = trace();
    return !t.empty() && t.back().device[0] == 0.102 && std::abs(force(t.back()) - expected) < 1e-6 * expected;
  })) << "never settled on the contacts' force";
  const std::vector<TraceSample> t = trace();
  double largest = 0.0;
  std::size_t rising = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double dt = std::max(t[i].time - t[i - 1].time, 1e-3);
    largest = std::max(largest, std::abs(force(t[i]) - force(t[i - 1])) * 1e-3 / dt);
    rising += force(t[i]) > 0.0 && force(t[i]) < 0.99 * expected;
  }
  // Without the fade the gate's rate limit, 0.3 N a millisecond, is the step.
  EXPECT_LT(largest, 0.15) << "per millisecond";
  EXPECT_GT(rising, 20u) << "a fade over tens of ticks, not a switch";
}

// Started already in contact: the force ramps in from zero the same way,
// not at the gate's rate.
TEST_F(Fidelity, StartingInContactRampsTheForceIn) {
  ASSERT_NO_FATAL_FAILURE(make_world(0.102, coupling::ToolMode::Free));
  world_->step();
  const double expected = glm::length(world_->wrench(tool_).force);
  device_.x0 = 0.102;
  ASSERT_NO_FATAL_FAILURE(start());
  ASSERT_TRUE(wait_for([&] {
    const std::vector<TraceSample> t = trace();
    return !t.empty() && std::abs(force(t.back()) - expected) < 1e-6 * expected;
  }));
  const std::vector<TraceSample> t = trace();
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double dt = std::max(t[i].time - t[i - 1].time, 1e-3);
    ASSERT_LT(std::abs(force(t[i]) - force(t[i - 1])) * 1e-3 / dt, 0.15) << "tick " << t[i].tick;
  }
}

}  // namespace
}  // namespace prox::runtime
