#include "runtime/threads.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <system_error>

#include "runtime/platform.h"

namespace prox::runtime {
namespace {


// x y z, then the rotation as a quaternion w x y z.
void pose_words(const Pose& pose, double out[7]) {
  const glm::dquat q = glm::quat_cast(pose.rotation);
  const double w[7] = {pose.translation.x, pose.translation.y, pose.translation.z, q.w, q.x, q.y, q.z};
  std::copy(w, w + 7, out);
}

using Clock = std::chrono::steady_clock;

bool finite(double v) { return std::isfinite(v); }

// What a device is handed: the gate's output, whether the gate changed it,
// the closest distance, and the world's distances a device maps it by.
DeviceWrench device_wrench(const Wrench& w, bool limited, double closest, const WorldSettings& world) {
  return {{w.force.x, w.force.y, w.force.z},
          {w.torque.x, w.torque.y, w.torque.z},
          limited,
          closest,
          world.force.safety_distance,
          world.cutoff()};
}

// A device's pose as a Pose, or false when it is not one (non-finite, or a
// quaternion too far from unit length to be a rotation).
bool pose_from_device(const DevicePose& d, Pose& pose) {
  for (double v : d.position)
    if (!finite(v)) return false;
  double norm2 = 0.0;
  for (double v : d.rotation) {
    if (!finite(v)) return false;
    norm2 += v * v;
  }
  if (!(norm2 > 0.25 && norm2 < 4.0)) return false;
  const double k = 1.0 / std::sqrt(norm2);
  const glm::dquat q(d.rotation[0] * k, d.rotation[1] * k, d.rotation[2] * k, d.rotation[3] * k);
  pose.rotation = glm::mat3_cast(q);
  pose.translation = Vec3(d.position[0], d.position[1], d.position[2]);
  return true;
}

void count(std::atomic<std::uint64_t>& counter, std::uint64_t n = 1) {
  counter.fetch_add(n, std::memory_order_relaxed);
}

}  // namespace

void default_cores(int cores[3]) { platform::default_cores(cores); }

Threads::Threads(World& world, const ThreadSettings& settings) : world_(world), settings_(settings) {
  epoch_ = Clock::now();
  local_view_ = global_view_ = world.view();
  auto first = std::make_unique<ToolSet>();
  for (std::uint32_t i = 0; i < world.body_slots(); ++i) {
    if (!world.is_tool(i)) continue;
    tools_.push_back(make_tool(i));
    first->tools.push_back(tools_.back().get());
  }
  publish(std::move(first));
  for (auto& p : pinned_) p.store(-1);
}

Threads::~Threads() { stop(); }

bool Threads::check(const ThreadSettings& s, Status& status) {
  auto bad = [&status](const std::string& message) {
    status = Status(StatusCode::InvalidArgument, message);
    return false;
  };
  // At least 1 Hz: a thread sleeps until its next deadline, so a longer
  // period would delay stopping by as much (and a tiny rate's period would
  // not fit a clock's nanosecond count at all).
  if (!(finite(s.haptic_rate) && s.haptic_rate >= 1.0 && s.haptic_rate <= 100000.0))
    return bad("haptic rate must be in [1, 100000] Hz (it is " + std::to_string(s.haptic_rate) + ")");
  if (!(finite(s.local_rate) && (s.local_rate == 0.0 || s.local_rate >= 1.0)))
    return bad("local rate must be 0 (back to back) or >= 1 Hz (it is " + std::to_string(s.local_rate) + ")");
  if (!(finite(s.global_rate) && (s.global_rate == 0.0 || s.global_rate >= 1.0)))
    return bad("global rate must be 0 (back to back) or >= 1 Hz (it is " + std::to_string(s.global_rate) +
               ")");
  if (!(finite(s.stale_after) && s.stale_after > 0.0))
    return bad("staleness limit must be > 0 s (it is " + std::to_string(s.stale_after) + ")");
  if (!(finite(s.max_force_rate) && s.max_force_rate > 0.0))
    return bad("maximum force rate must be > 0 N/s (it is " + std::to_string(s.max_force_rate) + ")");
  if (!(finite(s.max_torque_rate) && s.max_torque_rate > 0.0))
    return bad("maximum torque rate must be > 0 N m/s (it is " + std::to_string(s.max_torque_rate) + ")");
  if (!(finite(s.trust_distance) && s.trust_distance >= 0.0))
    return bad("trust distance must be >= 0 (it is " + std::to_string(s.trust_distance) + ")");
  if (s.max_contacts < 1 || s.max_contacts > kMaxContactsPerTool)
    return bad("maximum contacts per tool must be in [1, 1048576] (it is " + std::to_string(s.max_contacts) +
               ")");
  if (s.global_workers < 1 || s.global_workers > 256)
    return bad("global workers must be in [1, 256] (it is " + std::to_string(s.global_workers) + ")");
  if (s.trace_capacity < 0 || s.trace_capacity > kMaxTraceCapacity)
    return bad("trace capacity must be in [0, 1048576] ticks (it is " + std::to_string(s.trace_capacity) + ")");
  const double haptic_period = 1.0 / s.haptic_rate;
  if (s.haptic_timing != HapticTiming::Auto && s.haptic_timing != HapticTiming::Sleep &&
      s.haptic_timing != HapticTiming::Spin)
    return bad("haptic timing is not auto, sleep or spin");
  if (!(finite(s.spin_margin) && s.spin_margin >= 0.0 && s.spin_margin <= haptic_period))
    return bad("spin margin must be in [0, the haptic period " + std::to_string(haptic_period) +
               "] s (it is " + std::to_string(s.spin_margin) + ")");
  const char* prioritised[2] = {"haptic", "local"};
  for (int r = 0; r < 2; ++r)
    if (s.realtime_priority[r] < 0 || s.realtime_priority[r] > 99)
      return bad(std::string(prioritised[r]) +
                 " thread's real-time priority must be 0 (none) or in [1, 99] (it is " +
                 std::to_string(s.realtime_priority[r]) + ")");
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  const char* names[3] = {"haptic", "local", "global"};
  for (int r = 0; r < 3; ++r)
    if (s.cores[r] < -1 || (cores > 0 && s.cores[r] >= cores))
      return bad(std::string(names[r]) + " thread's core " + std::to_string(s.cores[r]) +
                 " is not -1 or in [0, " + std::to_string(cores) + ")");
  return true;
}

bool Threads::start(Status& status) {
  const ThreadSettings& s = settings_;
  if (!check(s, status)) return false;
  if (s.trust_distance == 0.0) settings_.trust_distance = world_.settings().cutoff();
  loop_stats_[int(Role::Haptic)].reset(s.haptic_rate);
  loop_stats_[int(Role::Local)].reset(s.local_rate);
  loop_stats_[int(Role::Global)].reset(s.global_rate);
  stop_.store(0);
  for (int r = 0; r < 3; ++r) priority_[r].store(0), priority_error_[r].store(0);
  try {
    threads_[int(Role::Global)] = std::thread([this] { global_main(); });
    threads_[int(Role::Local)] = std::thread([this] { local_main(); });
    threads_[int(Role::Haptic)] = std::thread([this] { haptic_main(); });
  } catch (const std::system_error& e) {
    // The system refused a thread: stop the ones already running.
    request_stop();
    for (std::thread& t : threads_)
      if (t.joinable()) t.join();
    status = Status(StatusCode::Unsupported, std::string("cannot start the runtime's threads: ") + e.what());
    return false;
  }
  started_ = true;
  if (s.lock_memory) {
    // Now, with the threads' stacks and the snapshots' storage mapped.
    const int error = platform::lock_process_memory();
    memory_locked_.store(error == 0);
    memory_lock_error_.store(error);
  }
  return true;
}

void Threads::stop() {
  if (!started_) return;
  for (auto& s : stalled_) s.store(false);
  request_stop();
  for (std::thread& t : threads_)
    if (t.joinable()) t.join();
  started_ = false;
}

double Threads::now() const { return std::chrono::duration<double>(Clock::now() - epoch_).count(); }

void Threads::configure(Role role) {
  const int r = int(role);
  const int core = settings_.cores[r];
  const int priority = role == Role::Global ? 0 : settings_.realtime_priority[r];
  if (core >= 0 && platform::pin_current_thread(core)) pinned_[r].store(core);
  // The thread's precise wait is set up here, before the loop (on Windows
  // it is a timer the thread keeps, allocated once).
  const platform::SleepTimer sleep_timer = platform::prepare_precise_waits();
  if (role == Role::Haptic) sleep_timer_.store(int(sleep_timer));
  if (priority > 0) {
    const int error = platform::set_current_thread_realtime(priority);
    priority_[r].store(error == 0 ? priority : 0);
    priority_error_[r].store(error);
  }
  if (role == Role::Haptic) {
    HapticTiming timing = settings_.haptic_timing;
    if (timing == HapticTiming::Auto) {
      // A core of its own: pinned, and no other thread of ours pinned there.
      const bool own_core = pinned_[r].load() >= 0 && settings_.cores[int(Role::Local)] != core &&
                            settings_.cores[int(Role::Global)] != core;
      timing = priority_[r].load() > 0 || own_core ? HapticTiming::Spin : HapticTiming::Sleep;
    }
    timing_.store(timing);
  }
}

double Threads::cpu_seconds(Role role) const {
  return platform::thread_cpu_seconds(const_cast<std::thread&>(threads_[int(role)]));
}

ThreadGrant Threads::grant(Role role) const {
  const int r = int(role);
  return {pinned_[r].load(std::memory_order_relaxed), priority_[r].load(std::memory_order_relaxed),
          priority_error_[r].load(std::memory_order_relaxed)};
}

void Threads::request_stop() {
  stop_.store(1);
  platform::wake_all(stop_);
}

void Threads::sleep_until(double deadline) const {
  platform::sleep_until(stop_, epoch_ + std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(deadline)));
}

void Threads::wait_until(Role role, double deadline) const {
  const bool spin = role == Role::Haptic && timing_.load(std::memory_order_relaxed) == HapticTiming::Spin;
  sleep_until(spin ? deadline - settings_.spin_margin : deadline);
  if (spin)
    while (now() < deadline && !stop_.load(std::memory_order_relaxed)) platform::cpu_relax();
}

bool Threads::wait_while_stalled(Role role) {
  if (!stalled_[int(role)].load(std::memory_order_relaxed)) return false;
  while (stalled_[int(role)].load(std::memory_order_relaxed) && !stop_.load(std::memory_order_relaxed))
    sleep_until(now() + 1e-3);
  return true;
}

void Threads::pace(Role role, double period, double start, double& previous_start, double& deadline) {
  const double end = now();
  bool overrun = false;
  if (period > 0.0) {
    deadline += period;
    // Missed the next tick: start it now rather than trying to catch up.
    if (end > deadline) overrun = true, deadline = end;
  }
  loop_stats_[int(role)].record(previous_start < 0.0 ? 0.0 : start - previous_start, end - start, overrun);
  previous_start = start;
  if (period > 0.0) wait_until(role, deadline);
}

// ---- haptic -----------------------------------------------------------------

void Threads::haptic_main() {
  configure(Role::Haptic);
  const double period = 1.0 / settings_.haptic_rate;
  double deadline = now(), previous = -1.0, last_tick = now();
  while (!stop_.load(std::memory_order_relaxed)) {
    if (wait_while_stalled(Role::Haptic)) {
      deadline = last_tick = now();
      previous = -1.0;
      continue;
    }
    const double start = now();
    const double dt = start - last_tick;
    last_tick = start;
    for (Tool* tool : acquire(Role::Haptic).tools) {
      const int retiring = tool->retiring.load(std::memory_order_acquire);
      if (retiring == 0) {
        haptic_tick(*tool, start, dt);
      } else if (retiring == 1 && fade_step(*tool, std::min(dt, 1e-3))) {
        tool->retiring.store(2, std::memory_order_release);  // the device is called no more
      }
    }
    pace(Role::Haptic, period, start, previous, deadline);
  }
  // Stopping must not drop the force at once: fade every device out at the
  // gate's rates first (a few milliseconds at the defaults), in ticks of at
  // most a millisecond, so a slow loop does not make the fade slow too (the
  // gate takes at most kMaxStep of a longer tick).
  const double fade_tick = std::min(period, 1e-3);
  const ToolSet& set = acquire(Role::Haptic);
  for (int tick = 0; tick < 10000; ++tick) {
    bool zero = true;
    for (Tool* tool : set.tools)
      if (tool->retiring.load(std::memory_order_acquire) != 2) zero = fade_step(*tool, fade_tick) && zero;
    if (zero) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(fade_tick));
  }
}

bool Threads::fade_step(Tool& tool, double dt) {
  const Wrench w = tool.filter.step(Wrench{}, false, dt);
  if (tool.device.attached()) tool.device->write_wrench(device_wrench(w, true, kNoContact, world_.settings()));
  tool.wrench.store({w});
  if (tool.trace) {
    const Pose device = tool.pose.load().pose;
    // The device is told the fade is the gate's doing (clipped).
    record(tool, now(), device, device, w, kNoContact, 0, kTraceFaded | kTraceStopping | kTraceClipped);
  }
  return glm::length(w.force) == 0.0 && glm::length(w.torque) == 0.0;
}

void Threads::haptic_tick(Tool& tool, double t, double dt) {
  PoseSample sample;
  bool ok = true;
  if (tool.device.attached()) {
    DevicePose d{};
    ok = tool.device->read_pose(&d) && pose_from_device(d, sample.pose);
  } else {
    sample = tool.game_pose.load();
  }
  if (ok) {
    sample.time = t;
    tool.pose.store(sample);
  } else {
    count(invalid_poses_);
  }
  std::uint32_t flags = ok ? 0u : kTraceNoPose;

  // The contacts about to be replaced: what they give at this pose, so
  // that the switch is no step (only on the ticks a new snapshot comes).
  if (ok && tool.snapshots.fresh()) tool.renderer.replacing(tool.snapshots.front(), sample.pose);
  tool.snapshots.update();
  const ContactSnapshot& snapshot = tool.snapshots.front();
  bool valid = ok && snapshot.sequence > 0;
  if (valid && snapshot_checksum(snapshot) != snapshot.checksum) count(torn_snapshots_), valid = false;
  if (valid && t - snapshot.time > settings_.stale_after) count(stale_ticks_), valid = false, flags |= kTraceStale;
  // A constrained tool's device is meant to be away from its proxy: the
  // coupling's spring is what tells the hand, so only a free tool's
  // contacts can be left behind by it.
  if (valid && !tool.constrained &&
      pose_displacement(snapshot.tool_pose, sample.pose, tool.reference_local, snapshot.radius) >
          settings_.trust_distance)
    count(untrusted_ticks_), valid = false, flags |= kTraceUntrusted;
  // A tick whose contacts are not trusted (stale, left behind, no pose this
  // tick) tells the device the last trusted distance: a stall of the
  // tracking thread is not the contact going away.
  double closest = snapshot.sequence > 0 ? tool.closest : kNoContact;
  Pose proxy;
  const Wrench target =
      tool.renderer.render(snapshot, sample.pose, dt, valid, tool.filter.output(), &proxy, &closest);
  if (tool.constrained && valid) tool.rendered.store({proxy, t});
  tool.closest = closest;
  bool limited = false;
  const Wrench w = tool.filter.step(target, valid, dt, &limited);
  if (limited) count(limited_ticks_);
  if (tool.device.attached()) tool.device->write_wrench(device_wrench(w, limited, closest, world_.settings()));
  tool.wrench.store({w});
  if (tool.trace) {
    if (limited) flags |= kTraceClipped;
    if (!valid) flags |= kTraceFaded;
    // Without a pose this tick, the last one read (the tool's pose seqlock).
    const Pose device = ok ? sample.pose : tool.pose.load().pose;
    record(tool, t, device, tool.constrained ? proxy : device, w, closest,
           valid ? static_cast<std::uint32_t>(snapshot.contacts.size()) : 0u, flags);
  }
}

void Threads::record(Tool& tool, double t, const Pose& device, const Pose& proxy, const Wrench& w,
                     double closest, std::uint32_t contacts, std::uint32_t flags) {
  TraceSample s;
  s.tick = tool.trace->written();  // the samples before this one
  s.time = t;
  pose_words(device, s.device);
  pose_words(proxy, s.proxy);
  s.force[0] = w.force.x, s.force[1] = w.force.y, s.force[2] = w.force.z;
  s.torque[0] = w.torque.x, s.torque[1] = w.torque.y, s.torque[2] = w.torque.z;
  s.closest = closest;
  s.contacts = contacts;
  s.flags = flags;
  tool.trace->push(s);
}

// ---- the game thread's side --------------------------------------------------------

StepStats Threads::step_stats() const {
  std::lock_guard<std::mutex> lock(results_mutex_);
  return step_stats_;
}

HapticCounters Threads::haptic_counters() const {
  HapticCounters c;
  c.invalid_poses = invalid_poses_.load(std::memory_order_relaxed);
  c.stale_ticks = stale_ticks_.load(std::memory_order_relaxed);
  c.untrusted_ticks = untrusted_ticks_.load(std::memory_order_relaxed);
  c.limited_ticks = limited_ticks_.load(std::memory_order_relaxed);
  c.torn_snapshots = torn_snapshots_.load(std::memory_order_relaxed);
  c.dropped_contacts = dropped_contacts_.load(std::memory_order_relaxed);
  return c;
}

}  // namespace prox::runtime
