// The threaded runtime on the bunny scene, with real threads and the
// built-in scripted device: functional properties only (rates and jitter are
// for the benchmark). The haptic output must stay finite, bounded and
// rate-limited through faults (a stalled tracker, NaN poses, a teleporting
// pose), the threads must all make progress, and the haptic thread must
// never allocate. At rest the threads must agree with the deterministic step.
#include "runtime/threads_fixture.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <new>
#include <random>
#include <thread>
#include <utility>

namespace prox::runtime {
namespace {

using prox::testing::load_obj_model;
using prox::testing::make_query;
using Clock = std::chrono::steady_clock;

TEST_F(ThreadsTest, ApproachAndRestAgreeWithTheDeterministicStep) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  // Every thread made progress.
  Threads& threads = *world_->threads();
  EXPECT_GT(threads.loop_summary(Role::Haptic).updates, 100u);
  EXPECT_GT(threads.loop_summary(Role::Local).updates, 10u);
  EXPECT_GT(threads.loop_summary(Role::Global).updates, 1u);
  // At rest the tracked set becomes the global search's: same contacts
  // (those too far to move the force may come a global search later).
  std::vector<Contact> contacts;
  EXPECT_TRUE(wait_until([&] {
    world_->contacts(tool_, contacts);
    return contacts.size() == expected_.lmds.size();
  }));
  const Pose pose = world_->current_pose(tool_);
  EXPECT_LE(length(pose.translation - near_.translation), 1e-12);
  EXPECT_GT(world_->stats().pairs_in_range, 0);
  expect_safe_output();
  // Stopping fades the device out rather than dropping the force.
  world_->stop_threads();
  EXPECT_EQ(length(scripted_->record().last_force), 0.0);
  expect_safe_output();
  // And the results stay readable after the stop.
  world_->contacts(tool_, contacts);
  EXPECT_EQ(contacts.size(), expected_.lmds.size());
}

// The global search split over two helpers finds what one thread finds:
// at rest, the deterministic step's contacts.
TEST_F(ThreadsTest, GlobalSearchOnTwoWorkersAgreesWithTheDeterministicStep) {
  settings_.global_workers = 2;
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  std::vector<Contact> contacts;
  EXPECT_TRUE(wait_until([&] {
    world_->contacts(tool_, contacts);
    return contacts.size() == expected_.lmds.size();
  }));
  std::vector<double> found, expected;
  for (const Contact& c : contacts) found.push_back(c.lmd.distance);
  for (const LmdPair& p : expected_.lmds) expected.push_back(p.distance);
  std::sort(found.begin(), found.end());
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-15) << "contact " << i;
  EXPECT_TRUE(at_rest_force());
  expect_safe_output();
}

// Every thread at 4 Hz sleeps a quarter of a second between iterations:
// stopping wakes them rather than waiting for the end of the period, and
// the haptic loop fades the force out in ticks of a millisecond, not in its
// own (each of which the gate would let take only 5 ms of the fade).
TEST_F(ThreadsTest, StoppingASlowLoopWaitsNeitherForItsPeriodNorForASlowFade) {
  settings_.haptic_rate = settings_.local_rate = settings_.global_rate = 4.0;
  settings_.stale_after = 2.0;  // a snapshot a quarter of a second old is fresh here
  // The gate's rate: the whole force in four steps of 5 ms, so its fade
  // takes several steps.
  const double force = length(expected_wrench_.force);
  settings_.max_force_rate = force / (4 * 0.005);
  scripted_ = std::make_unique<ScriptedDevice>(std::vector<ScriptedPose>{ScriptedPose::of(near_)}, 1.0, false);
  world_->set_device(tool_, Device::borrowed(*scripted_));
  Status status;
  ASSERT_TRUE(world_->start_threads(settings_, status)) << status.message();
  // Seen within milliseconds of the tick that wrote it: the haptic thread is
  // asleep for about a quarter of a second more.
  ASSERT_TRUE(wait_until([&] { return length(scripted_->record().last_force) > 0.6 * force; }, 10.0));
  const auto before = Clock::now();
  world_->stop_threads();
  const double seconds = std::chrono::duration<double>(Clock::now() - before).count();
  EXPECT_LT(seconds, 0.1) << "stopping waited for the period or faded in its ticks";
  EXPECT_EQ(length(scripted_->record().last_force), 0.0) << "stopping dropped the force rather than fading it";
  expect_safe_output();
}

TEST_F(ThreadsTest, StalledTrackerFadesOutAndRecovers) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  Threads& threads = *world_->threads();
  threads.stall(Role::Local, true);
  ASSERT_TRUE(faded_out()) << "stale contacts kept a force on the device";
  EXPECT_GT(threads.haptic_counters().stale_ticks, 0u);
  threads.stall(Role::Local, false);
  EXPECT_TRUE(settled());
  expect_safe_output();
}

// The device is told the closest distance of the contacts (at rest, the
// least of the engine's LMD distances there) with the world's safety
// distance and cutoff; a stalled tracker, whose stale contacts fade the
// force out, does not make it "no contact"; stopping does.
TEST_F(ThreadsTest, TheDeviceIsToldTheClosestDistanceAndAStallKeepsIt) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  double least = std::numeric_limits<double>::infinity();
  for (const LmdPair& p : expected_.lmds) least = std::min(least, p.distance);
  ASSERT_TRUE(wait_until([&] { return std::fabs(device->closest.load() - least) <= 1e-9; }))
      << "told " << device->closest.load() << " m, the LMDs' least is " << least << " m";
  EXPECT_EQ(device->safety_distance.load(), world_settings_.force.safety_distance);
  EXPECT_EQ(device->cutoff.load(), world_settings_.cutoff());
  Threads& threads = *world_->threads();
  threads.stall(Role::Local, true);
  ASSERT_TRUE(faded_out());
  EXPECT_GT(threads.haptic_counters().stale_ticks, 0u);
  EXPECT_NEAR(device->closest.load(), least, 1e-9) << "a stall is not the contact going away";
  threads.stall(Role::Local, false);
  EXPECT_TRUE(settled());
  world_->stop_threads();
  EXPECT_EQ(device->closest.load(), std::numeric_limits<double>::infinity()) << "stopped: no contact";
  expect_safe_output();
}

TEST_F(ThreadsTest, StalledGlobalSearchKeepsTheForce) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  Threads& threads = *world_->threads();
  threads.stall(Role::Global, true);
  const std::uint64_t local_before = threads.loop_summary(Role::Local).updates;
  EXPECT_TRUE(wait_until([&] { return threads.loop_summary(Role::Local).updates > local_before + 50; }));
  EXPECT_TRUE(at_rest_force()) << "local tracking alone holds the contacts";
  threads.stall(Role::Global, false);
  expect_safe_output();
}

// The tool leaves its contacts' range and comes back to the very pose the
// global search last saw, all while the search is busy (stalled here, slow
// on a loaded machine): local tracking dropped the contacts out there, and
// only the global search can bring them back, though the pose it sees next
// is the one it has already searched.
TEST_F(ThreadsTest, AnExcursionTheGlobalSearchMissesDoesNotLoseTheContacts) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  Threads& threads = *world_->threads();
  threads.stall(Role::Global, true);
  // Parked once its iteration in flight has ended: no more updates.
  std::uint64_t seen = threads.loop_summary(Role::Global).updates;
  ASSERT_TRUE(wait_until([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const std::uint64_t now = threads.loop_summary(Role::Global).updates;
    return std::exchange(seen, now) == now;
  }));
  device->fault.store(FaultyDevice::Teleport);
  std::vector<Contact> contacts;
  ASSERT_TRUE(wait_until([&] {
    world_->contacts(tool_, contacts);
    return contacts.empty();
  })) << "local tracking kept contacts 20 cm away";
  device->fault.store(FaultyDevice::None);
  // Tracked back at the resting pose, with nothing left to track.
  const std::uint64_t local_before = threads.loop_summary(Role::Local).updates;
  ASSERT_TRUE(wait_until([&] { return threads.loop_summary(Role::Local).updates > local_before + 10; }));
  threads.stall(Role::Global, false);
  EXPECT_TRUE(settled()) << "the contacts lost out there never came back";
  world_->contacts(tool_, contacts);
  EXPECT_EQ(contacts.size(), expected_.lmds.size());
  expect_safe_output();
}

TEST_F(ThreadsTest, NaNAndMissingPosesFadeOutAndRecover) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  for (int fault : {FaultyDevice::NaNPose, FaultyDevice::NoPose}) {
    device->fault.store(fault);
    ASSERT_TRUE(faded_out()) << "fault " << fault;
    device->fault.store(FaultyDevice::None);
    EXPECT_TRUE(settled()) << "fault " << fault;
  }
  EXPECT_GT(world_->threads()->haptic_counters().invalid_poses, 0u);
  const Pose pose = world_->current_pose(tool_);
  EXPECT_TRUE(std::isfinite(pose.translation.y)) << "a NaN pose never reaches the trackers";
  expect_safe_output();
}

TEST_F(ThreadsTest, TeleportingPoseDoesNotSpike) {
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  // Local tracking held, so that no snapshot can catch up with the jump
  // (on a loaded machine it otherwise might, between the haptic loop's pose
  // and its force): the contacts are fresh but tracked 20 cm away.
  Threads& threads = *world_->threads();
  threads.stall(Role::Local, true);
  device->fault.store(FaultyDevice::Teleport);
  EXPECT_TRUE(wait_until([&] { return threads.haptic_counters().untrusted_ticks > 0; }));
  ASSERT_TRUE(faded_out()) << "contacts tracked 20 cm away were rendered";
  threads.stall(Role::Local, false);
  device->fault.store(FaultyDevice::None);
  EXPECT_TRUE(settled());
  expect_safe_output();
}

TEST_F(ThreadsTest, ToolMovedByTheGameThread) {
  // No device: the game thread's set_pose moves the tool while the threads run.
  Status status;
  ASSERT_TRUE(world_->start_threads(settings_, status)) << status.message();
  EXPECT_EQ(length(world_->wrench(tool_).force), 0.0);
  world_->set_pose(tool_, near_);
  EXPECT_TRUE(wait_until([&] { return at_rest_force(); }));
  std::vector<Contact> contacts;
  EXPECT_TRUE(wait_until([&] {
    world_->contacts(tool_, contacts);
    return contacts.size() == expected_.lmds.size();
  }));
  EXPECT_EQ(world_->threads()->haptic_counters().torn_snapshots, 0u);
}

TEST_F(ThreadsTest, ASmallSnapshotKeepsTheClosestContacts) {
  ASSERT_GT(expected_.lmds.size(), 1u);
  settings_.max_contacts = 1;
  const LmdPair closest =
      *std::min_element(expected_.lmds.begin(), expected_.lmds.end(),
                        [](const LmdPair& a, const LmdPair& b) { return a.distance < b.distance; });
  expected_wrench_ = tool_wrench(world_settings_.force, {closest}, near_.apply(bunny_->centre));
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  EXPECT_GT(world_->threads()->haptic_counters().dropped_contacts, 0u);
  // The far contacts do not move the force here, so settling does not wait
  // for the global search to find them at the resting pose; it will.
  std::vector<Contact> contacts;
  EXPECT_TRUE(wait_until([&] {
    world_->contacts(tool_, contacts);
    return contacts.size() == expected_.lmds.size();
  })) << "the game thread sees every contact, not only the one the haptic loop gets";
  expect_safe_output();
}

// The spinning wait (and a real-time priority, where the system grants it)
// changes how the loop waits, not what it does: the same answer at rest,
// and still no allocation.
TEST_F(ThreadsTest, SpinningRealTimeLoopAgreesAndAllocatesNothing) {
  settings_.haptic_timing = HapticTiming::Spin;
  settings_.realtime_priority[0] = 10;
  FaultyDevice* device = nullptr;
  start_and_settle(device);
  EXPECT_EQ(world_->threads()->haptic_timing(), HapticTiming::Spin);
  EXPECT_GT(world_->threads()->loop_summary(Role::Haptic).updates, 100u);
  expect_safe_output();
}

// An engine's thread pushes poses at 90 Hz through the streamed device: the
// tool approaches and comes to rest at the deterministic step's wrench, and
// neither the haptic thread nor the pushing thread allocates.
TEST_F(ThreadsTest, StreamedDeviceDrivesTheToolWithoutAllocating) {
  StreamSettings stream_settings;
  stream_settings.mode = StreamMode::Interpolate;
  StreamDevice stream(stream_settings);
  FaultyDevice marked(stream);
  world_->set_device(tool_, Device::borrowed(marked));
  const ScriptedDevice path({ScriptedPose::of(far_), ScriptedPose::of(near_)}, 0.5, false);
  std::atomic<bool> stop{false};
  std::thread engine([&] {
    prox::testing::mark_this_thread(
        true);  // counted like the haptic thread: pushing must not allocate either
    const double start = stream_clock();
    while (!stop.load()) {
      const double now = stream_clock();
      const ScriptedPose p = path.pose_at(now - start);
      StreamSample sample;
      sample.time = now;
      for (int k = 0; k < 3; ++k) sample.position[k] = p.position[k];
      for (int k = 0; k < 4; ++k) sample.rotation[k] = p.rotation[k];
      stream.push(sample);
      std::this_thread::sleep_for(std::chrono::microseconds(11111));
    }
  });
  Status status;
  ASSERT_TRUE(world_->start_threads(settings_, status)) << status.message();
  const bool rested = wait_until([&] { return at_rest_force(); });
  stop.store(true);
  engine.join();
  EXPECT_TRUE(rested) << "the streamed tool never reached the deterministic answer at rest";
  const StreamStats st = stream.stats();
  EXPECT_GT(st.pushed, 20u);
  EXPECT_GT(st.reads, 100u);
  const DeviceWrench w = stream.wrench();
  EXPECT_TRUE(std::isfinite(w.force[0] + w.force[1] + w.force[2]));
  EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread or the pusher allocated";
  // The devices are this test's locals: stop the haptic thread (which
  // writes to them until it stops) before they go, not in TearDown.
  world_->stop_threads();
}

TEST_F(ThreadsTest, BadSettingsAreRefusedByName) {
  struct Case {
    std::function<void(ThreadSettings&)> spoil;
    const char* word;
  };
  const Case cases[] = {
      {[](ThreadSettings& s) { s.haptic_rate = 0.0; }, "haptic rate"},
      {[](ThreadSettings& s) { s.haptic_rate = std::numeric_limits<double>::quiet_NaN(); }, "haptic rate"},
      {[](ThreadSettings& s) { s.local_rate = -1.0; }, "local rate"},
      {[](ThreadSettings& s) { s.global_rate = std::numeric_limits<double>::infinity(); }, "global rate"},
      {[](ThreadSettings& s) { s.stale_after = 0.0; }, "staleness"},
      {[](ThreadSettings& s) { s.max_force_rate = -3.0; }, "force rate"},
      {[](ThreadSettings& s) { s.max_torque_rate = 0.0; }, "torque rate"},
      {[](ThreadSettings& s) { s.trust_distance = -1.0; }, "trust distance"},
      {[](ThreadSettings& s) { s.max_contacts = 0; }, "contacts"},
      {[](ThreadSettings& s) { s.max_contacts = 1 << 30; }, "contacts"},
      {[](ThreadSettings& s) { s.cores[1] = 4096; }, "local thread's core"},
      {[](ThreadSettings& s) { s.global_workers = 0; }, "global workers"},
      {[](ThreadSettings& s) { s.global_workers = 257; }, "global workers"},
  };
  for (const Case& c : cases) {
    ThreadSettings s;
    c.spoil(s);
    Status status;
    prox::testing::reset_marked_counts();
    bool started = false;
    {
      prox::testing::MarkedScope marked;
      started = world_->start_threads(s, status);
    }
    EXPECT_FALSE(started) << c.word;
    EXPECT_NE(status.message().find(c.word), std::string::npos) << status.message();
    EXPECT_FALSE(world_->running());
    // Refused before the snapshots' storage is reserved (max_contacts
    // contacts, three times a tool): nothing bigger than the message.
    EXPECT_LT(prox::testing::marked_largest_allocation(), 1024u) << c.word;
  }
  prox::testing::reset_marked_counts();
}

}  // namespace
}  // namespace prox::runtime
