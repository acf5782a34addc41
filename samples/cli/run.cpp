// proxima run: the threaded runtime in real time, with a built-in device.
#include "cli.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <memory>

namespace proxcli {
namespace {

// The pose `t` seconds along a path of poses, `seconds_per_pose` apart:
// linear in position, along the shorter arc in rotation; the last pose
// after the end. What the scripted device does, for the streamed one's feed.
proxPose pose_along(const std::vector<proxPose>& path, double seconds_per_pose, double t) {
  const double u = std::max(0.0, t / seconds_per_pose);
  if (u >= static_cast<double>(path.size() - 1)) return path.back();
  const auto i = static_cast<std::size_t>(u);
  const double f = u - static_cast<double>(i);
  const proxPose &a = path[i], &b = path[i + 1];
  proxQuat qa = a.rotation;
  const proxQuat& qb = b.rotation;
  double dot = qa.w * qb.w + qa.x * qb.x + qa.y * qb.y + qa.z * qb.z;
  if (dot < 0.0) qa = {-qa.w, -qa.x, -qa.y, -qa.z}, dot = -dot;
  double ka = 1.0 - f, kb = f;
  if (dot < 0.9995) {  // slerp; nearly equal rotations interpolate linearly
    const double angle = std::acos(std::min(1.0, dot));
    ka = std::sin(ka * angle) / std::sin(angle);
    kb = std::sin(kb * angle) / std::sin(angle);
  }
  proxPose p;
  p.position = {a.position.x + (b.position.x - a.position.x) * f,
                a.position.y + (b.position.y - a.position.y) * f,
                a.position.z + (b.position.z - a.position.z) * f};
  p.rotation = {ka * qa.w + kb * qb.w, ka * qa.x + kb * qb.x, ka * qa.y + kb * qb.y, ka * qa.z + kb * qb.z};
  return p;  // the library normalises the quaternion
}

// What a device was handed, from the scripted device's own record or from
// the recording wrapper around a streamed device.
struct DeviceFigures {
  uint64_t reads = 0, writes = 0;
  double max_force = 0.0, max_torque = 0.0, max_force_step = 0.0;
  bool all_finite = true;
};

// Wraps the streamed device's callbacks to keep the figures the scripted
// device keeps itself. Runs on the haptic thread: atomics, no lock, no
// allocation, as every device callback must.
struct Recording {
  proxDeviceDef inner{};
  std::atomic<uint64_t> reads{0}, writes{0};
  std::atomic<double> max_force{0.0}, max_torque{0.0}, max_force_step{0.0};
  std::atomic<bool> all_finite{true};
  proxVec3 last{0.0, 0.0, 0.0};  // the haptic thread's own

  proxDeviceDef def() {
    proxDeviceDef d = proxDefaultDeviceDef();
    d.userData = this;
    d.readPose = [](void* user, proxPose* pose) -> proxBool {
      auto* self = static_cast<Recording*>(user);
      self->reads.fetch_add(1, std::memory_order_relaxed);
      return self->inner.readPose(self->inner.userData, pose);
    };
    d.writeWrench = [](void* user, const proxWrench* w) {
      auto* self = static_cast<Recording*>(user);
      self->inner.writeWrench(self->inner.userData, w);
      const double f = length(w->force), t = length(w->torque);
      if (!std::isfinite(f + t)) self->all_finite.store(false, std::memory_order_relaxed);
      auto raise = [](std::atomic<double>& max, double v) {
        if (v > max.load(std::memory_order_relaxed)) max.store(v, std::memory_order_relaxed);
      };
      raise(self->max_force, f);
      raise(self->max_torque, t);
      if (self->writes.load(std::memory_order_relaxed) > 0)
        raise(self->max_force_step, length(sub(w->force, self->last)));
      self->last = w->force;
      self->writes.fetch_add(1, std::memory_order_relaxed);
    };
    return d;
  }
  DeviceFigures figures() const {
    return {reads.load(),      writes.load(),         max_force.load(),
            max_torque.load(), max_force_step.load(), all_finite.load()};
  }
};

// --realtime's SCHED_FIFO priorities: the haptic loop above local tracking,
// both above every ordinary thread and below the kernel's own (99).
constexpr int32_t kHapticPriority = 80, kLocalPriority = 70;

// What the system granted a thread's real-time request, in words.
std::string grant_text(const proxThreadStats& s, int32_t asked) {
  if (asked == 0) return "not asked";
  if (s.realtimePriority > 0) return "SCHED_FIFO " + std::to_string(s.realtimePriority);
  return std::string("refused: ") + std::strerror(s.realtimeError) +
         (s.realtimeError == EPERM ? " (needs root, CAP_SYS_NICE or an RLIMIT_RTPRIO)" : "");
}

proxStreamMode parse_stream_mode(const std::string& s) {
  if (s == "hold") return PROX_STREAM_HOLD;
  if (s == "interpolate") return PROX_STREAM_INTERPOLATE;
  if (s == "extrapolate") return PROX_STREAM_EXTRAPOLATE;
  fail("--stream-mode: '" + s + "' is not hold, interpolate or extrapolate");
}

std::string fmt_ms(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g ms", seconds * 1e3);
  return text;
}

const char* stream_mode_name(proxStreamMode m) {
  return m == PROX_STREAM_HOLD ? "hold" : m == PROX_STREAM_EXTRAPOLATE ? "extrapolate" : "interpolate";
}

// --tool-mode constrained: what the proxy and the device pose did. The
// proxy's exact distance comes from proxBody_GetDistance (a constrained
// tool's distance is its proxy's); whether the device pose is inside, from a
// second world holding a free copy of the tool placed at the device pose
// (proxBody_GetPose of a constrained tool). While it crosses, the device's
// penetration is taken as its distance from the proxy.
struct ProxyWatch {
  Scene ghost;
  double min_proxy_distance = INFINITY;
  double max_device_penetration = 0.0;
  uint64_t samples = 0;

  ProxyWatch(const Settings& settings, const std::string& path_a, const std::string& path_b,
             const proxPose& start)
      : ghost(settings, path_a, path_b, identity(), start) {}

  void sample(const Scene& scene, const proxPose& device) {
    double d = 0.0;
    check(proxBody_GetDistance(scene.a(), scene.b(), INFINITY, &d));
    min_proxy_distance = std::min(min_proxy_distance, d);
    proxPose proxy;
    check(proxBody_GetProxyPose(scene.b(), &proxy));
    check(proxBody_SetPose(ghost.b(), &device));
    double device_distance = 0.0;
    check(proxBody_GetDistance(ghost.a(), ghost.b(), 0.0, &device_distance));
    if (device_distance == 0.0)
      max_device_penetration = std::max(max_device_penetration, length(sub(device.position, proxy.position)));
    ++samples;
  }
};

}  // namespace

// `run`: the threaded runtime in real time. B moves along path T (or the
// --poses path) in --seconds, then holds still for --hold. The scripted
// device (the default) moves it on the haptic thread at 1 kHz; the streamed
// device is fed by a second thread of this program at --stream-rate (90 Hz),
// as an engine's frame loop would feed it, and the haptic loop interpolates.
// Proxima's haptic, local and global threads do the rest while this thread
// samples the results every 100 ms, as a renderer would.
int run(Args& args) {
  std::string path_a = default_asset("bunny.obj"), path_b;
  std::string poses_path, json_path, trace_path, device_kind = "scripted";
  double seconds = 2.0, hold = 0.5, stream_rate = 90.0;
  proxStreamMode stream_mode = PROX_STREAM_INTERPOLATE;
  Settings settings = preset(PROX_FORCE_PRESET_HARD);
  proxThreadsDef threads = proxDefaultThreadsDef();
  proxToolMode tool_mode = PROX_TOOL_FREE;
  int animate[2] = {-1, -1};  // A's and B's glTF animation played while the threads run; -1: none
  if (!args.empty() && args.peek().rfind("--", 0) != 0) {
    path_a = args.next("mesh A");
    path_b = args.next("mesh B");
  }
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--seconds") {
      seconds = parse_number(args.next("--seconds value"), "--seconds");
      if (!(seconds > 0.0 && seconds <= 3600.0)) fail("--seconds must be in (0, 3600]");
    } else if (opt == "--hold") {
      hold = parse_number(args.next("--hold value"), "--hold");
      if (!(hold >= 0.0 && hold <= 3600.0)) fail("--hold must be in [0, 3600]");
    } else if (opt == "--method") {
      settings.method = parse_method(args.next("--method value"));
      if (settings.method == PROX_METHOD_REFERENCE)
        fail("run: the reference method is too slow for real time");
    } else if (opt == "--force") {
      const proxMethod method = settings.method;
      settings = parse_force(args.next("--force value"));
      settings.method = method;
    } else if (opt == "--poses") {
      poses_path = args.next("--poses file");
    } else if (opt == "--json") {
      json_path = args.next("--json file");
    } else if (opt == "--trace") {
      trace_path = args.next("--trace file");
    } else if (opt == "--animate-a" || opt == "--animate-b") {
      const double index = parse_number(args.next((opt + " INDEX").c_str()), opt.c_str());
      if (index < 0 || index > 2147483647.0 || index != std::floor(index))
        fail(opt + ": the animation index is not a whole number >= 0");
      animate[opt == "--animate-a" ? 0 : 1] = static_cast<int32_t>(index);
    } else if (opt == "--device") {
      device_kind = args.next("--device value");
      if (device_kind != "scripted" && device_kind != "stream" && !is_hid_kind(device_kind))
        fail("--device: '" + device_kind + "' is not scripted, stream or hid[:VVVV:PPPP]");
    } else if (opt == "--stream-rate") {
      stream_rate = parse_number(args.next("--stream-rate value"), "--stream-rate");
      if (!(stream_rate >= 1.0 && stream_rate <= 10000.0)) fail("--stream-rate must be in [1, 10000] Hz");
    } else if (opt == "--stream-mode") {
      stream_mode = parse_stream_mode(args.next("--stream-mode value"));
    } else if (opt == "--haptic-timing") {
      const std::string timing = args.next("--haptic-timing value");
      if (timing == "spin")
        threads.hapticTiming = PROX_TIMING_SPIN;
      else if (timing == "sleep")
        threads.hapticTiming = PROX_TIMING_SLEEP;
      else if (timing == "auto")
        threads.hapticTiming = PROX_TIMING_AUTO;
      else
        fail("--haptic-timing: '" + timing + "' is not auto, spin or sleep");
    } else if (opt == "--spin-margin") {
      threads.spinMargin = parse_number(args.next("--spin-margin value"), "--spin-margin");
    } else if (opt == "--realtime") {
      threads.hapticPriority = kHapticPriority;
      threads.localPriority = kLocalPriority;
    } else if (opt == "--lock-memory") {
      threads.lockMemory = 1;
    } else if (opt == "--tool-mode") {
      // The constrained tool (docs/coupling.md).
      const std::string mode = args.next("--tool-mode value");
      if (mode == "free")
        tool_mode = PROX_TOOL_FREE;
      else if (mode == "constrained")
        tool_mode = PROX_TOOL_CONSTRAINED;
      else
        fail("--tool-mode: '" + mode + "' is not free or constrained");
    } else {
      fail("run: unknown option '" + opt + "'");
    }
  }
  const bool streamed = device_kind == "stream";
  const bool hid = is_hid_kind(device_kind);  // the tool follows the device from the path's start
  if (path_b.empty()) path_b = path_a;
  const bool constrained = tool_mode == PROX_TOOL_CONSTRAINED;
  auto scene_ptr = std::make_unique<Scene>(settings, path_a, path_b, identity(), identity());
  std::vector<proxPose> path;
  if (!poses_path.empty()) {
    path = read_poses(poses_path);
    std::printf("run: %s held along %s (%zu poses in %.3g s, then %.3g s still) against %s, cutoff %.3g m\n",
                path_b.c_str(), poses_path.c_str(), path.size(), seconds, hold, path_a.c_str(),
                settings.cutoff);
  } else {
    const double far = kPathFar, near = kPathNear;
    path = {translation(x_at_gap(*scene_ptr, far)), translation(x_at_gap(*scene_ptr, near))};
    std::printf(
        "run: path T, %s held and moved along +x against %s from %.3g m to %.3g m apart in %.3g s, "
        "then %.3g s still, cutoff %.3g m\n",
        path_b.c_str(), path_a.c_str(), far, near, seconds, hold, settings.cutoff);
  }
  const double seconds_per_pose = seconds / static_cast<double>(path.size() - 1);
  // A constrained tool's proxy starts where it is created: where the path
  // does, clear of A.
  std::unique_ptr<ProxyWatch> watch;
  if (constrained) {
    scene_ptr = std::make_unique<Scene>(settings, path_a, path_b, identity(), path.front(), tool_mode);
    watch = std::make_unique<ProxyWatch>(settings, path_a, path_b, path.front());
  }
  Scene& scene = *scene_ptr;
  check(proxBody_SetPose(scene.b(), &path.front()));

  proxScriptedDeviceId scripted{};
  proxStreamDeviceId stream{};
  Recording recording;
  proxDeviceDef device_def;
  std::shared_ptr<HidRun> hid_run;  // closed before the scene goes
  if (hid) {
    proxMeshInfo info;
    check(proxMesh_GetInfo(scene.mesh_b(), &info));
    hid_run = open_hid(device_kind, scene.world(), path.front(), centre(info), &recording.inner);
    device_def = recording.def();
    std::printf("device: HID %s, read on its own thread\n", hid_description(*hid_run).c_str());
  } else if (streamed) {
    proxStreamDeviceDef def = proxDefaultStreamDeviceDef();
    def.mode = stream_mode;
    def.delay = 1.0 / stream_rate;  // one frame: a sample on either side
    check(proxWorld_CreateStreamDevice(scene.world(), &def, &stream));
    check(proxStreamDevice_GetDeviceDef(stream, &recording.inner));
    device_def = recording.def();
    std::printf("device: streamed, fed at %.3g Hz by a second thread, %s\n", stream_rate,
                stream_mode_name(stream_mode));
  } else {
    proxScriptedDeviceDef def = proxDefaultScriptedDeviceDef();
    def.poses = path.data();
    def.poseCount = static_cast<int32_t>(path.size());
    def.secondsPerPose = seconds_per_pose;
    check(proxWorld_CreateScriptedDevice(scene.world(), &def, &scripted));
    check(proxScriptedDevice_GetDeviceDef(scripted, &device_def));
    std::printf("device: scripted, read by the haptic loop at 1 kHz\n");
  }
  check(proxBody_SetDevice(scene.b(), &device_def));

  if (!trace_path.empty()) threads.traceCapacity = trace_capacity_for(seconds + hold, threads.hapticRate);
  check(proxWorld_StartThreads(scene.world(), &threads));
  // The engine's frame loop for the streamed device: the pose the path has
  // now, stamped now, once a frame (its own thread, as an engine's would be).
  std::atomic<bool> stop_feed{false};
  std::atomic<int> feed_errors{0};
  std::thread feed;
  // Joined on every way out, a failed call's included.
  struct Join {
    std::atomic<bool>& stop;
    std::thread& thread;
    ~Join() {
      stop = true;
      if (thread.joinable()) thread.join();
    }
  } join_feed{stop_feed, feed};
  if (streamed) {
    feed = std::thread([&] {
      const double start = proxGetTime();
      for (long frame = 0; !stop_feed.load(); ++frame) {
        const double due = start + static_cast<double>(frame) / stream_rate;
        std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, due - proxGetTime())));
        const double now = proxGetTime();
        const proxPose pose = pose_along(path, seconds_per_pose, now - start);
        if (proxStreamDevice_PushPose(stream, &pose, now) != PROX_SUCCESS) ++feed_errors;
      }
    });
  }
  // The animations played, as a game's frame loop would pose its meshes
  // (each looping over its keyframes).
  const proxMeshId animated_mesh[2] = {scene.mesh_a(), scene.mesh_b()};
  proxAnimationInfo animation[2] = {};
  long animation_frames = 0;
  for (int m = 0; m < 2; ++m)
    if (animate[m] >= 0) {
      int32_t count = 0;
      check(proxMesh_GetAnimationCount(animated_mesh[m], &count));
      if (animate[m] >= count)
        fail(std::string(m ? "--animate-b" : "--animate-a") + ": animation " + std::to_string(animate[m]) +
             " does not exist (the mesh has " + std::to_string(count) + ")");
      check(proxMesh_GetAnimationInfo(animated_mesh[m], animate[m], &animation[m]));
      std::printf("animation: %s's \"%s\" (%.3g s), played at 60 Hz while the threads run\n", m ? "B" : "A",
                  animation[m].name, animation[m].duration - animation[m].start);
    }
  const bool animating = animate[0] >= 0 || animate[1] >= 0;
  std::printf("%8s %12s %9s %12s\n", "time s", "tool x m", "contacts", "|force| N");
  const auto start = std::chrono::steady_clock::now();
  // A constrained tool's proxy is measured every 10 ms, animations posed
  // every 1/60 s (a row printed every 100 ms).
  const int per_row = constrained ? 10 : animating ? 6 : 1;
  for (int frame = 0;; ++frame) {
    const double t = 0.1 * frame / per_row;
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                              std::chrono::duration<double>(t)));
    for (int m = 0; m < 2; ++m)
      if (animate[m] >= 0) {
        const double length = animation[m].duration - animation[m].start;
        check(proxMesh_Animate(animated_mesh[m], animate[m],
                               animation[m].start + (length > 0.0 ? std::fmod(t, length) : 0.0)));
        ++animation_frames;
      }
    proxPose pose;
    check(proxBody_GetPose(scene.b(), &pose));
    if (watch) watch->sample(scene, pose);
    if (frame % per_row == 0)
      std::printf("%8.1f %12.6f %9zu %12.4f\n", t, pose.position.x, scene.contacts().size(),
                  length(scene.wrench().force));
    if (t >= seconds + hold - 1e-9) break;
  }
  check(proxWorld_StopThreads(scene.world()));
  stop_feed = true;
  if (feed.joinable()) feed.join();
  if (feed_errors.load() > 0)
    fail("run: the streamed device refused " + std::to_string(feed_errors.load()) + " poses");

  const char* names[3] = {"haptic", "local", "global"};
  proxThreadStats stats[3];
  std::printf("%-7s %10s %10s %11s %11s %11s %11s %9s %9s\n", "thread", "target Hz", "rate Hz", "period p50",
              "period p99", "period max", "work p99", "updates", "overruns");
  for (int i = 0; i < 3; ++i) {
    check(proxWorld_GetThreadStats(scene.world(), static_cast<proxThread>(i), &stats[i]));
    const proxThreadStats& s = stats[i];
    std::printf("%-7s %10.0f %10.0f %8.3f ms %8.3f ms %8.3f ms %8.3f ms %9llu %9llu\n", names[i],
                s.targetRate, s.achievedRate, s.periodP50 * 1e3, s.periodP99 * 1e3, s.periodMax * 1e3,
                s.updateP99 * 1e3, static_cast<unsigned long long>(s.updates),
                static_cast<unsigned long long>(s.overruns));
  }
  const bool spun = stats[0].timing == PROX_TIMING_SPIN;
  std::printf("haptic timing: %s%s%s; real time: haptic %s, local %s",
              threads.hapticTiming == PROX_TIMING_AUTO ? "auto, so " : "", spun ? "spin" : "sleep",
              spun ? (" (the last " + fmt_ms(threads.spinMargin) + " of each period)").c_str() : "",
              grant_text(stats[0], threads.hapticPriority).c_str(),
              grant_text(stats[1], threads.localPriority).c_str());
  if (threads.lockMemory)
    std::printf("; memory %s",
                stats[0].memoryLocked
                    ? "locked"
                    : (std::string("not locked: ") + std::strerror(stats[0].memoryLockError)).c_str());
  std::printf("\n");
  proxSafetyStats safety;
  check(proxWorld_GetSafetyStats(scene.world(), &safety));
  DeviceFigures device;
  proxStreamDeviceStats stream_stats{};
  if (hid) {
    device = recording.figures();
  } else if (streamed) {
    device = recording.figures();
    check(proxStreamDevice_GetStats(stream, &stream_stats));
  } else {
    proxScriptedDeviceRecord r;
    check(proxScriptedDevice_GetRecord(scripted, &r));
    device = {r.reads, r.writes, r.maxForce, r.maxTorque, r.maxForceStep, r.allFinite != 0};
  }
  std::printf(
      "device: %llu poses read, %llu wrenches written; largest force %.4f N, largest change between "
      "ticks %.4f N; %s\n",
      static_cast<unsigned long long>(device.reads), static_cast<unsigned long long>(device.writes),
      device.max_force, device.max_force_step, device.all_finite ? "all finite" : "NOT ALL FINITE");
  if (hid) print_hid_stats(*hid_run);
  if (streamed)
    std::printf(
        "stream: %llu samples pushed, %llu dropped, %llu refused; interval mean %.2f ms, max %.2f ms; "
        "%llu ticks past the newest sample, %llu stale ticks\n",
        static_cast<unsigned long long>(stream_stats.samplesPushed),
        static_cast<unsigned long long>(stream_stats.samplesDropped),
        static_cast<unsigned long long>(stream_stats.samplesRefused), stream_stats.meanSampleInterval * 1e3,
        stream_stats.maxSampleInterval * 1e3, static_cast<unsigned long long>(stream_stats.extrapolatedTicks),
        static_cast<unsigned long long>(stream_stats.staleTicks));
  std::printf(
      "safety: %llu invalid poses, %llu stale ticks, %llu untrusted ticks, %llu limited ticks, "
      "%llu torn snapshots\n",
      static_cast<unsigned long long>(safety.invalidPoses),
      static_cast<unsigned long long>(safety.staleTicks),
      static_cast<unsigned long long>(safety.untrustedTicks),
      static_cast<unsigned long long>(safety.limitedTicks),
      static_cast<unsigned long long>(safety.tornSnapshots));

  if (!trace_path.empty()) {
    const std::size_t ticks = write_trace_csv(scene.b(), threads.traceCapacity, trace_path);
    std::printf("trace: %zu haptic ticks written to %s\n", ticks, trace_path.c_str());
  }
  if (watch)
    std::printf(
        "proxy: closest %.6g m to the other body (safety distance %.6g m); the device went %.6g m "
        "inside\n",
        watch->min_proxy_distance, settings.force.safetyDistance, watch->max_device_penetration);

  if (!json_path.empty()) {
    auto count = [](uint64_t n) { return static_cast<long long>(n); };
    Json j;
    j.begin_object();
    j.key("method").value(method_name(settings.method));
    j.key("cutoff").value(settings.cutoff);
    j.key("haptic_timing").value(stats[0].timing == PROX_TIMING_SPIN ? "spin" : "sleep");
    j.key("spin_margin_ms").value(threads.spinMargin * 1e3);
    j.key("memory_locked").value(stats[0].memoryLocked != 0);
    j.key("animation_frames").value(static_cast<long long>(animation_frames));
    j.key("threads").begin_object();
    for (int i = 0; i < 3; ++i) {
      const proxThreadStats& s = stats[i];
      j.key(names[i]).begin_object();
      j.key("target_hz").value(s.targetRate);
      j.key("achieved_hz").value(s.achievedRate);
      j.key("period_p50_ms").value(s.periodP50 * 1e3);
      j.key("period_p99_ms").value(s.periodP99 * 1e3);
      j.key("period_p999_ms").value(s.periodP999 * 1e3);
      j.key("period_max_ms").value(s.periodMax * 1e3);
      j.key("update_p50_ms").value(s.updateP50 * 1e3);
      j.key("update_p99_ms").value(s.updateP99 * 1e3);
      j.key("update_max_ms").value(s.updateMax * 1e3);
      j.key("updates").value(count(s.updates));
      j.key("overruns").value(count(s.overruns));
      if (i < 2) {
        j.key("realtime_priority").value(s.realtimePriority);
        j.key("realtime_error").value(s.realtimeError);
      }
      j.end_object();
    }
    j.end_object();
    j.key("device").begin_object();
    j.key("kind").value(device_kind);
    j.key("reads").value(count(device.reads));
    j.key("writes").value(count(device.writes));
    j.key("max_force").value(device.max_force);
    j.key("max_torque").value(device.max_torque);
    j.key("max_force_step").value(device.max_force_step);
    j.key("all_finite").value(device.all_finite);
    j.end_object();
    if (streamed) {
      j.key("stream").begin_object();
      j.key("mode").value(stream_mode_name(stream_mode));
      j.key("rate_hz").value(stream_rate);
      j.key("samples_pushed").value(count(stream_stats.samplesPushed));
      j.key("samples_dropped").value(count(stream_stats.samplesDropped));
      j.key("samples_refused").value(count(stream_stats.samplesRefused));
      j.key("reads").value(count(stream_stats.reads));
      j.key("stale_ticks").value(count(stream_stats.staleTicks));
      j.key("extrapolated_ticks").value(count(stream_stats.extrapolatedTicks));
      j.key("mean_sample_interval_ms").value(stream_stats.meanSampleInterval * 1e3);
      j.key("max_sample_interval_ms").value(stream_stats.maxSampleInterval * 1e3);
      j.key("max_extrapolation_ms").value(stream_stats.maxExtrapolation * 1e3);
      j.end_object();
    }
    j.key("tool_mode").value(constrained ? "constrained" : "free");
    if (watch) {
      j.key("min_proxy_distance").value(watch->min_proxy_distance);
      j.key("max_device_penetration").value(watch->max_device_penetration);
      j.key("proxy_samples").value(static_cast<long long>(watch->samples));
    }
    if (hid) hid_json(*hid_run, j);
    j.key("safety").begin_object();
    j.key("invalid_poses").value(count(safety.invalidPoses));
    j.key("stale_ticks").value(count(safety.staleTicks));
    j.key("untrusted_ticks").value(count(safety.untrustedTicks));
    j.key("limited_ticks").value(count(safety.limitedTicks));
    j.key("torn_snapshots").value(count(safety.tornSnapshots));
    j.key("dropped_contacts").value(count(safety.droppedContacts));
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return device.all_finite ? 0 : 1;
}

}  // namespace proxcli
