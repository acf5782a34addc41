// The streamed device through the C API, with real threads: misuse of every
// function; an engine thread pushing at 90 Hz with jitter, drops and
// reordering; staleness and recovery; the wrench read from another thread
// while the haptic loop writes it; two threads pushing at once; and no
// allocation and no lock on the haptic thread or in PushPose.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "support/marked_threads.h"
#include "two_cubes.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <random>
#include <thread>
#include <vector>

namespace {

using prox::testing::mark_this_thread;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using capi_test::at;
using capi_test::length;
using capi_test::wait_until;
proxVec3 minus(const proxVec3& a, const proxVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

void sleep_seconds(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

// A device around the streamed device's def that records, on the haptic
// thread, every pose it renders and every wrench it is handed, into storage
// reserved before the threads start.
struct Recorder {
  static constexpr int kCapacity = 60000;  // a minute of ticks
  proxDeviceDef inner{};
  std::unique_ptr<double[]> x{new double[kCapacity]};
  std::unique_ptr<proxVec3[]> force{new proxVec3[kCapacity]};
  std::atomic<int> poses{0}, wrenches{0};

  proxDeviceDef def() {
    proxDeviceDef d = proxDefaultDeviceDef();
    d.readPose = [](void* user, proxPose* pose) -> proxBool {
      mark_this_thread(true);
      auto* self = static_cast<Recorder*>(user);
      if (!self->inner.readPose(self->inner.userData, pose)) return 0;
      const int i = self->poses.load(std::memory_order_relaxed);
      if (i < kCapacity) self->x[i] = pose->position.x, self->poses.store(i + 1, std::memory_order_release);
      return 1;
    };
    d.writeWrench = [](void* user, const proxWrench* w) {
      auto* self = static_cast<Recorder*>(user);
      self->inner.writeWrench(self->inner.userData, w);
      const int i = self->wrenches.load(std::memory_order_relaxed);
      if (i < kCapacity) self->force[i] = w->force, self->wrenches.store(i + 1, std::memory_order_release);
    };
    d.userData = this;
    return d;
  }
};

// Two 10 cm cubes: the wall static at the origin, the tool beside it along
// +x, moved by a streamed device from 3 cm away (beyond the cutoff) to 7 mm.
class Stream : public capi_test::TwoCubes {
 protected:
  static constexpr double kFar = 0.13, kNear = 0.107;

  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(create_scene(kNear));
    // The deterministic step's wrench at the near pose: what the threads
    // must render there.
    ASSERT_OK(proxWorld_Step(world));
    ASSERT_OK(proxBody_GetWrench(tool, &expected));
    ASSERT_GT(length(expected.force), 0.01);
    ASSERT_FALSE(expected.clipped);
    const proxPose far = at(kFar);
    ASSERT_OK(proxBody_SetPose(tool, &far));
    ASSERT_OK(proxWorld_Step(world));  // the threads start from this step's (zero) wrench
    ASSERT_TRUE(zero());
    threads = proxDefaultThreadsDef();
  }
  void TearDown() override {
    stop_engine();
    if (proxWorld_IsValid(world)) EXPECT_OK(proxWorld_Destroy(world));
  }

  void create(proxStreamMode mode, double stale_after = 0.05) {
    proxStreamDeviceDef def = proxDefaultStreamDeviceDef();
    def.mode = mode;
    def.staleAfter = stale_after;
    ASSERT_OK(proxWorld_CreateStreamDevice(world, &def, &device));
    ASSERT_OK(proxStreamDevice_GetDeviceDef(device, &recorder.inner));
    const proxDeviceDef d = recorder.def();
    ASSERT_OK(proxBody_SetDevice(tool, &d));
  }

  // An engine thread pushing the pose at `x_of(t)` (t seconds since it
  // started) at 90 Hz, each push `jitter` seconds early or late at random;
  // `skip` of the samples never sent, `swap` of them sent two frames late.
  void start_engine(std::function<double(double)> x_of, double jitter = 0.0, double skip = 0.0,
                    double swap = 0.0) {
    engine_stop = false;
    engine = std::thread([=] {
      std::mt19937_64 rng(7);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      const double start = proxGetTime();
      bool holding = false;
      int held_for = 0;
      proxPose held{};
      double held_time = 0.0;
      for (int frame = 0; !engine_stop.load(); ++frame) {
        const double due = start + frame / 90.0 + jitter * (2.0 * u(rng) - 1.0);
        sleep_seconds(std::max(0.0, due - proxGetTime()));
        const double t = start + frame / 90.0;  // when the pose is true
        const proxPose pose = at(x_of(t - start));
        if (u(rng) < skip) continue;
        if (!holding && u(rng) < swap) {
          held = pose, held_time = t, holding = true, held_for = 0;  // sent two frames late
          continue;
        }
        mark_this_thread(true);
        const proxResult now = proxStreamDevice_PushPose(device, &pose, t);
        const bool send_late = holding && ++held_for == 2;
        const proxResult late =
            send_late ? proxStreamDevice_PushPose(device, &held, held_time) : PROX_SUCCESS;
        mark_this_thread(false);
        push_results.push_back(now);
        if (send_late) push_results.push_back(late), holding = false;
      }
    });
  }
  void stop_engine() {
    engine_stop = true;
    if (engine.joinable()) engine.join();
  }

  bool at_expected() const {
    proxWrench w{};
    proxBody_GetWrench(tool, &w);
    return length(minus(w.force, expected.force)) <= 1e-9 * length(expected.force);
  }
  bool zero() const {
    proxWrench w{};
    proxBody_GetWrench(tool, &w);
    return length(w.force) == 0.0;
  }

  // The wrench never jumps by more than the safety gate lets it (its rate
  // times its longest step, 5 ms), and never passes the maximum.
  void expect_gated() const {
    const int n = recorder.wrenches.load(std::memory_order_acquire);
    ASSERT_GT(n, 50);
    double worst = 0.0, largest = 0.0;
    for (int i = 1; i < n; ++i) {
      worst = std::max(worst, length(minus(recorder.force[i], recorder.force[i - 1])));
      largest = std::max(largest, length(recorder.force[i]));
    }
    EXPECT_LE(worst, threads.maxForceRate * 0.005 + 1e-9);
    EXPECT_LE(largest, max_force + 1e-12);
  }

  proxWrench expected{};
  proxThreadsDef threads{};
  proxStreamDeviceId device{};
  Recorder recorder;
  std::thread engine;
  std::atomic<bool> engine_stop{false};
  std::vector<int> push_results;  // the engine thread's own until joined
};

TEST_F(Stream, DefsAreValidatedByName) {
  proxStreamDeviceDef def = proxDefaultStreamDeviceDef();
  EXPECT_EQ(def.mode, PROX_STREAM_INTERPOLATE);
  EXPECT_NEAR(def.delay, 1.0 / 90.0, 1e-15);
  EXPECT_EQ(def.maxExtrapolation, 0.02);
  EXPECT_EQ(def.staleAfter, 0.05);
  proxStreamDeviceId id{};
  EXPECT_FAILS(proxWorld_CreateStreamDevice(world, nullptr, &id), PROX_ERROR_INVALID_ARGUMENT, "def");
  EXPECT_FAILS(proxWorld_CreateStreamDevice(world, &def, nullptr), PROX_ERROR_INVALID_ARGUMENT, "device");
  proxStreamDeviceDef raw{};
  EXPECT_FAILS(proxWorld_CreateStreamDevice(world, &raw, &id), PROX_ERROR_INVALID_ARGUMENT,
               "proxDefaultStreamDeviceDef");
  struct Case {
    std::function<void(proxStreamDeviceDef&)> spoil;
    const char* word;
  };
  const Case cases[] = {
      {[](proxStreamDeviceDef& d) { d.mode = static_cast<proxStreamMode>(7); }, "mode"},
      {[](proxStreamDeviceDef& d) { d.delay = -0.001; }, "delay"},
      {[](proxStreamDeviceDef& d) { d.delay = kNaN; }, "delay"},
      {[](proxStreamDeviceDef& d) { d.maxExtrapolation = -1.0; }, "maxExtrapolation"},
      {[](proxStreamDeviceDef& d) { d.maxExtrapolation = INFINITY; }, "maxExtrapolation"},
      {[](proxStreamDeviceDef& d) { d.staleAfter = 0.0; }, "staleAfter"},
      {[](proxStreamDeviceDef& d) { d.staleAfter = kNaN; }, "staleAfter"},
  };
  for (const Case& c : cases) {
    proxStreamDeviceDef d = proxDefaultStreamDeviceDef();
    c.spoil(d);
    EXPECT_FAILS(proxWorld_CreateStreamDevice(world, &d, &id), PROX_ERROR_INVALID_ARGUMENT, c.word);
    EXPECT_EQ(id.index1, 0u) << "a refused create leaves a null id";
  }
  EXPECT_FAILS(proxWorld_CreateStreamDevice(proxWorldId{}, &def, &id), PROX_ERROR_INVALID_HANDLE, "world");
}

TEST_F(Stream, BadIdsPosesAndTimesAreRefusedAndCounted) {
  create(PROX_STREAM_HOLD);
  const proxPose good = at(kFar);
  const double now = proxGetTime();
  EXPECT_GT(now, 0.0);
  proxWrench w{};
  proxDeviceDef dd{};
  proxStreamDeviceStats st{};
  // Ids.
  const proxStreamDeviceId null_id{};
  proxStreamDeviceId out_of_range = device;
  out_of_range.index1 = 1u << 30;
  proxStreamDeviceId foreign = device;
  foreign.world.generation += 1;
  for (const proxStreamDeviceId& bad : {null_id, out_of_range, foreign}) {
    EXPECT_FAILS(proxStreamDevice_PushPose(bad, &good, now), PROX_ERROR_INVALID_HANDLE, "device");
    EXPECT_FAILS(proxStreamDevice_GetWrench(bad, &w), PROX_ERROR_INVALID_HANDLE, "device");
    EXPECT_NE(proxStreamDevice_GetDeviceDef(bad, &dd), PROX_SUCCESS);
    EXPECT_NE(proxStreamDevice_GetStats(bad, &st), PROX_SUCCESS);
  }
  // Arguments.
  EXPECT_FAILS(proxStreamDevice_PushPose(device, nullptr, now), PROX_ERROR_INVALID_ARGUMENT, "pose");
  proxPose p = good;
  p.position.y = kNaN;
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &p, now), PROX_ERROR_INVALID_ARGUMENT, "position");
  p = good;
  p.position.z = -INFINITY;
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &p, now), PROX_ERROR_INVALID_ARGUMENT, "position");
  p = good;
  p.rotation.x = kNaN;
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &p, now), PROX_ERROR_INVALID_ARGUMENT, "rotation");
  p = good;
  p.rotation = {0, 0, 0, 0};
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &p, now), PROX_ERROR_INVALID_ARGUMENT, "zero quaternion");
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &good, -1.0), PROX_ERROR_INVALID_ARGUMENT, "timeSeconds");
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &good, kNaN), PROX_ERROR_INVALID_ARGUMENT, "timeSeconds");
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &good, INFINITY), PROX_ERROR_INVALID_ARGUMENT,
               "timeSeconds");
  EXPECT_FAILS(proxStreamDevice_GetWrench(device, nullptr), PROX_ERROR_INVALID_ARGUMENT, "wrench");
  EXPECT_FAILS(proxStreamDevice_GetDeviceDef(device, nullptr), PROX_ERROR_INVALID_ARGUMENT, "def");
  EXPECT_FAILS(proxStreamDevice_GetStats(device, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats");
  // A quaternion that is not unit is normalised; a duplicate is dropped.
  p = good;
  p.rotation = {2, 0, 0, 0};
  EXPECT_OK(proxStreamDevice_PushPose(device, &p, now));
  EXPECT_OK(proxStreamDevice_PushPose(device, &good, now));
  EXPECT_OK(proxStreamDevice_PushPose(device, &good, now - 1.0));
  EXPECT_OK(proxStreamDevice_GetStats(device, &st));
  EXPECT_EQ(st.samplesRefused, 8u);
  EXPECT_EQ(st.samplesPushed, 1u);
  EXPECT_EQ(st.samplesDropped, 2u);
  // Before the threads run, the wrench is zero.
  EXPECT_OK(proxStreamDevice_GetWrench(device, &w));
  EXPECT_EQ(length(w.force), 0.0);
}

// A device lives as long as its world: another world's tools cannot take it
// (destroying its world would leave them calling freed memory).
TEST_F(Stream, ADeviceHoldsOnlyItsOwnWorldsTools) {
  create(PROX_STREAM_HOLD);
  proxWorldId other{};
  const proxWorldDef wd = proxDefaultWorldDef();
  ASSERT_OK(proxCreateWorld(&wd, &other));
  proxStreamDeviceDef sd = proxDefaultStreamDeviceDef();
  proxStreamDeviceId foreign{};
  ASSERT_OK(proxWorld_CreateStreamDevice(other, &sd, &foreign));
  proxDeviceDef def{};
  ASSERT_OK(proxStreamDevice_GetDeviceDef(foreign, &def));
  EXPECT_FAILS(proxBody_SetDevice(tool, &def), PROX_ERROR_INVALID_ARGUMENT, "another world");
  const proxPose poses[2] = {at(kFar), at(kNear)};
  proxScriptedDeviceDef scd = proxDefaultScriptedDeviceDef();
  scd.poses = poses;
  scd.poseCount = 2;
  proxScriptedDeviceId scripted{};
  ASSERT_OK(proxWorld_CreateScriptedDevice(other, &scd, &scripted));
  ASSERT_OK(proxScriptedDevice_GetDeviceDef(scripted, &def));
  EXPECT_FAILS(proxBody_SetDevice(tool, &def), PROX_ERROR_INVALID_ARGUMENT, "another world");
  ASSERT_OK(proxWorld_Destroy(other));
  // This world's own device still holds the tool, and runs.
  ASSERT_OK(proxStreamDevice_GetDeviceDef(device, &def));
  EXPECT_OK(proxBody_SetDevice(tool, &def));
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  EXPECT_OK(proxWorld_StopThreads(world));
}

// A def whose callbacks are one built-in device's and whose pointer is
// another's, both of this world, is refused: the haptic loop would read the
// one device as the other.
// Every device of Proxima's reads through the same two callbacks (the
// device table's), so a def is taken for a device of Proxima's only when its
// userData is a live one: never a pointer of the application's.
TEST_F(Stream, TheTablesCallbacksTakeOnlyALiveDevice) {
  create(PROX_STREAM_HOLD);
  const proxPose poses[2] = {at(kFar), at(kNear)};
  proxScriptedDeviceDef scd = proxDefaultScriptedDeviceDef();
  scd.poses = poses;
  scd.poseCount = 2;
  proxScriptedDeviceId scripted{};
  ASSERT_OK(proxWorld_CreateScriptedDevice(world, &scd, &scripted));
  proxDeviceDef streamed{}, script{};
  ASSERT_OK(proxStreamDevice_GetDeviceDef(device, &streamed));
  ASSERT_OK(proxScriptedDevice_GetDeviceDef(scripted, &script));
  EXPECT_EQ(streamed.readPose, script.readPose);
  EXPECT_EQ(streamed.writeWrench, script.writeWrench);
  int not_a_device = 0;
  proxDeviceDef forged = streamed;
  forged.userData = &not_a_device;
  EXPECT_FAILS(proxBody_SetDevice(tool, &forged), PROX_ERROR_INVALID_ARGUMENT, "does not exist");
  // Each as it came holds the tool.
  EXPECT_OK(proxBody_SetDevice(tool, &script));
  EXPECT_OK(proxBody_SetDevice(tool, &streamed));
  // A destroyed one's def is refused by its kind's name, and its id everywhere.
  EXPECT_OK(proxScriptedDevice_Destroy(scripted));
  EXPECT_FAILS(proxBody_SetDevice(tool, &script), PROX_ERROR_INVALID_ARGUMENT, "scripted device that was destroyed");
  proxScriptedDeviceRecord record;
  EXPECT_FAILS(proxScriptedDevice_GetRecord(scripted, &record), PROX_ERROR_INVALID_HANDLE, "destroyed");
  EXPECT_FAILS(proxScriptedDevice_Destroy(scripted), PROX_ERROR_INVALID_HANDLE, "scripted device");
  EXPECT_FALSE(proxScriptedDevice_IsValid(scripted));
  EXPECT_TRUE(proxStreamDevice_IsValid(device));
}

// A slot freed by Destroy is taken by the next device; the old id, whose
// generation is gone, never names the new one.
TEST_F(Stream, AStaleIdNeverNamesTheDeviceNowInItsSlot) {
  create(PROX_STREAM_HOLD);
  const proxStreamDeviceId old = device;
  ASSERT_OK(proxStreamDevice_Destroy(old));
  proxStreamDeviceDef def = proxDefaultStreamDeviceDef();
  proxStreamDeviceId now{};
  ASSERT_OK(proxWorld_CreateStreamDevice(world, &def, &now));
  EXPECT_EQ(now.index1, old.index1);      // the same slot ...
  EXPECT_NE(now.reserved, old.reserved);  // ... in another generation
  const proxPose pose = at(kFar);
  EXPECT_FAILS(proxStreamDevice_PushPose(old, &pose, proxGetTime()), PROX_ERROR_INVALID_HANDLE, "destroyed");
  EXPECT_FALSE(proxStreamDevice_IsValid(old));
  EXPECT_OK(proxStreamDevice_PushPose(now, &pose, proxGetTime()));
  // A device of another kind in a streamed device's id is not taken for one.
  proxScriptedDeviceDef scd = proxDefaultScriptedDeviceDef();
  scd.poses = &pose;
  scd.poseCount = 1;
  proxScriptedDeviceId scripted{};
  ASSERT_OK(proxWorld_CreateScriptedDevice(world, &scd, &scripted));
  const proxStreamDeviceId disguised{scripted.index1, scripted.reserved, world};
  EXPECT_FAILS(proxStreamDevice_PushPose(disguised, &pose, proxGetTime()), PROX_ERROR_INVALID_HANDLE,
               "streamed device");
  device = now;
}

TEST_F(Stream, ThreadRulesAndTheWorldsEnd) {
  create(PROX_STREAM_HOLD);
  const proxPose good = at(kFar);
  // Push and GetWrench from any thread; the def and the stats only from the game thread.
  proxResult push = PROX_ERROR_INTERNAL, wrench = PROX_ERROR_INTERNAL, def = PROX_SUCCESS,
             stats = PROX_SUCCESS;
  std::thread other([&] {
    proxWrench w{};
    proxDeviceDef d{};
    proxStreamDeviceStats s{};
    push = proxStreamDevice_PushPose(device, &good, proxGetTime());
    wrench = proxStreamDevice_GetWrench(device, &w);
    def = proxStreamDevice_GetDeviceDef(device, &d);
    stats = proxStreamDevice_GetStats(device, &s);
  });
  other.join();
  EXPECT_EQ(push, PROX_SUCCESS);
  EXPECT_EQ(wrench, PROX_SUCCESS);
  EXPECT_EQ(def, PROX_ERROR_WRONG_THREAD);
  EXPECT_EQ(stats, PROX_ERROR_WRONG_THREAD);
  // The world destroyed while another thread pushes: its pushes start
  // failing cleanly, never touching a device that is gone.
  std::atomic<bool> invalid{false}, stop{false};
  std::atomic<long> bad{0};
  std::thread pusher([&] {
    while (!stop.load()) {
      const proxResult r = proxStreamDevice_PushPose(device, &good, proxGetTime());
      if (r == PROX_ERROR_INVALID_HANDLE)
        invalid = true;
      else if (r != PROX_SUCCESS)
        ++bad;
    }
  });
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  sleep_seconds(0.05);
  ASSERT_OK(proxWorld_Destroy(world));
  EXPECT_TRUE(wait_until([&] { return invalid.load(); }));
  stop = true;
  pusher.join();
  EXPECT_EQ(bad.load(), 0);
  proxWrench w{};
  EXPECT_FAILS(proxStreamDevice_PushPose(device, &good, proxGetTime()), PROX_ERROR_INVALID_HANDLE,
               "destroyed");
  EXPECT_FAILS(proxStreamDevice_GetWrench(device, &w), PROX_ERROR_INVALID_HANDLE, "device");
}

// The paper's figure of merit for a device: the rendered motion is smooth.
// Samples at 90 Hz, arriving up to 5 ms early or late, one in ten lost, one
// in ten sent two frames late (and so dropped): the pose the haptic
// loop renders moves monotonically along the approach, the force comes to
// the deterministic step's at rest, and never steps faster than the gate.
TEST_F(Stream, JitteredDroppedAndReorderedSamplesRenderAMonotoneApproach) {
  create(PROX_STREAM_INTERPOLATE);
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  start_engine([](double t) { return kFar + (kNear - kFar) * std::min(1.0, t / 0.8); }, 0.005, 0.1, 0.1);
  EXPECT_TRUE(wait_until([&] { return at_expected(); })) << "never came to the step's wrench at rest";
  sleep_seconds(0.2);
  stop_engine();
  ASSERT_OK(proxWorld_StopThreads(world));
  const int n = recorder.poses.load(std::memory_order_acquire);
  ASSERT_GT(n, 500);
  int backwards = 0;
  for (int i = 1; i < n; ++i) backwards += recorder.x[i] > recorder.x[i - 1] ? 1 : 0;
  EXPECT_EQ(backwards, 0) << "the rendered pose went back along the path";
  EXPECT_LE(std::fabs(recorder.x[n - 1] - kNear), 1e-12);
  expect_gated();
  proxStreamDeviceStats st{};
  ASSERT_OK(proxStreamDevice_GetStats(device, &st));
  EXPECT_GT(st.samplesDropped, 0u) << "the reordered samples arrive late";
  EXPECT_EQ(st.samplesPushed + st.samplesDropped, push_results.size());
  for (int r : push_results) EXPECT_EQ(r, PROX_SUCCESS);
  EXPECT_GT(st.meanSampleInterval, 1.0 / 90.0);  // some were lost
  EXPECT_GE(st.maxSampleInterval, 2.0 / 90.0 - 1e-9);
  EXPECT_GT(st.reads, st.samplesPushed);
}

TEST_F(Stream, SilenceFadesTheForceOutAndPushingAgainRestoresIt) {
  create(PROX_STREAM_HOLD);
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  start_engine([](double) { return kNear; });
  ASSERT_TRUE(wait_until([&] { return at_expected(); }));
  stop_engine();
  const double stopped = proxGetTime();
  ASSERT_TRUE(wait_until([&] { return zero(); }, 10.0));
  // staleAfter, then the gate's fade at its rate (with generous room for the
  // scheduler of a loaded machine: this is not a timing test).
  const double fade = length(expected.force) / threads.maxForceRate;
  EXPECT_LE(proxGetTime() - stopped, 0.05 + fade + 0.5);
  proxStreamDeviceStats st{};
  ASSERT_OK(proxStreamDevice_GetStats(device, &st));
  EXPECT_GT(st.staleTicks, 0u);
  proxSafetyStats safety{};
  ASSERT_OK(proxWorld_GetSafetyStats(world, &safety));
  EXPECT_GT(safety.invalidPoses, 0u);
  start_engine([](double) { return kNear; });
  EXPECT_TRUE(wait_until([&] { return at_expected(); })) << "pushing again did not restore the force";
  stop_engine();
  ASSERT_OK(proxWorld_StopThreads(world));
  expect_gated();
}

// GetWrench from another thread while the haptic loop writes it: always a
// whole wrench (ThreadSanitizer checks the handoff), equal to the tool's.
TEST_F(Stream, TheWrenchIsReadWholeFromAnyThread) {
  create(PROX_STREAM_INTERPOLATE);
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  start_engine([](double t) { return kFar + (kNear - kFar) * std::min(1.0, t / 0.5); });
  std::atomic<bool> stop{false};
  std::atomic<long> reads{0}, bad{0};
  std::thread reader([&] {
    while (!stop.load()) {
      proxWrench w{};
      if (proxStreamDevice_GetWrench(device, &w) != PROX_SUCCESS || !std::isfinite(length(w.force)) ||
          length(w.force) > max_force + 1e-12)
        ++bad;
      ++reads;
    }
  });
  EXPECT_TRUE(wait_until([&] { return at_expected(); }));
  sleep_seconds(0.05);
  stop = true;
  reader.join();
  EXPECT_GT(reads.load(), 100);
  EXPECT_EQ(bad.load(), 0);
  proxWrench from_device{}, from_tool{};
  ASSERT_OK(proxStreamDevice_GetWrench(device, &from_device));
  ASSERT_OK(proxBody_GetWrench(tool, &from_tool));
  EXPECT_LE(length(minus(from_device.force, expected.force)), 1e-9 * length(expected.force));
  EXPECT_LE(length(minus(from_tool.force, expected.force)), 1e-9 * length(expected.force));
  stop_engine();
}

// One pusher at a time: a second thread pushing at the same moment is told
// so, and every push is either taken, dropped as late, or refused that way.
TEST_F(Stream, TwoPushersAtOnceAreToldApart) {
  create(PROX_STREAM_HOLD);
  std::atomic<long> ok{0}, busy{0}, other{0};
  auto hammer = [&] {
    const proxPose p = at(kFar);
    for (int i = 0; i < 20000; ++i) {
      const proxResult r = proxStreamDevice_PushPose(device, &p, proxGetTime());
      if (r == PROX_SUCCESS)
        ++ok;
      else if (r == PROX_ERROR_WRONG_THREAD)
        ++busy;
      else
        ++other;
    }
  };
  std::thread a(hammer), b(hammer);
  a.join();
  b.join();
  EXPECT_EQ(other.load(), 0);
  EXPECT_EQ(ok.load() + busy.load(), 40000);
  proxStreamDeviceStats st{};
  ASSERT_OK(proxStreamDevice_GetStats(device, &st));
  EXPECT_EQ(long(st.samplesPushed + st.samplesDropped), ok.load());
}

TEST_F(Stream, ExtrapolationPredictsAtMostItsLimit) {
  create(PROX_STREAM_EXTRAPOLATE, 5.0);  // not stale however slowly the threads start
  // Two samples of a motion at 0.1 m/s along -x, the newest 1 ms ago; then
  // silence: the tool is predicted 20 ms past it (2 mm) and held there.
  const double now = proxGetTime();
  const proxPose a = at(0.12), b = at(0.12 - 0.1 / 90.0);
  ASSERT_OK(proxStreamDevice_PushPose(device, &a, now - 0.001 - 1.0 / 90.0));
  ASSERT_OK(proxStreamDevice_PushPose(device, &b, now - 0.001));
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  sleep_seconds(0.03);
  proxPose pose{};
  ASSERT_OK(proxBody_GetPose(tool, &pose));
  ASSERT_OK(proxWorld_StopThreads(world));
  EXPECT_NEAR(pose.position.x, b.position.x - 0.1 * 0.02, 1e-9);
  proxStreamDeviceStats st{};
  ASSERT_OK(proxStreamDevice_GetStats(device, &st));
  EXPECT_NEAR(st.maxExtrapolation, 0.02, 1e-12);
  EXPECT_GT(st.extrapolatedTicks, 0u);
}

TEST_F(Stream, NeitherTheHapticThreadNorPushPoseAllocatesOrLocks) {
  if (!prox::testing::kSeesLibrary)
    GTEST_SKIP() << "on Windows proxima.dll's allocations and locks cannot be counted from the test program "
                    "(the Linux build checks them)";
  create(PROX_STREAM_INTERPOLATE);
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  start_engine([](double t) { return kFar + (kNear - kFar) * std::min(1.0, t / 0.5); }, 0.003, 0.05, 0.05);
  EXPECT_TRUE(wait_until([&] { return at_expected(); }));
  proxWrench w{};
  EXPECT_OK(proxStreamDevice_GetWrench(device, &w));
  stop_engine();
  ASSERT_OK(proxWorld_StopThreads(world));
  EXPECT_GT(recorder.poses.load(), 100);
  EXPECT_EQ(prox::testing::marked_allocations(), 0) << "the haptic thread or PushPose allocated";
  EXPECT_EQ(prox::testing::marked_locks(), 0) << "the haptic thread or PushPose took a mutex";
  // The counting sees inside the library: a call that locks the world
  // registry, and a refusal (its message is a new string), are counted.
  mark_this_thread(true);
  proxWorld_IsValid(world);
  proxStreamDevice_PushPose(device, nullptr, 0.0);
  mark_this_thread(false);
  EXPECT_GT(prox::testing::marked_allocations(), 0);
  if (prox::testing::kCountsLocks) {
    EXPECT_GT(prox::testing::marked_locks(), 0);
  }
}

}  // namespace
