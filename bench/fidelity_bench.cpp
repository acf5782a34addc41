// What the hand feels, tick by tick (docs/haptic-fidelity.md): a device of
// the application's own (proxDeviceDef callbacks) moves the tool at a steady
// hand speed and records every wrench the haptic loop hands it, on the real
// threads. Per scene, force preset, tool mode and speed: the tool created
// 186 mm out, the device starting 3 mm beyond the cutoff (still for 150 ms,
// then moving), approaching to
// 0.1 mm from the surface (5 mm past it for a constrained tool), sliding
// 10 mm sideways and back, then held. Then the same device poses are
// replayed through the deterministic step, one step a tick, for the exact
// force at each (--no-exact skips it): the rendered force's error against
// it and the time shifts that best align the rendered force, and a
// constrained tool's proxy (the flight recorder's), with the exact ones.
// The C API alone; the flight recorder (0.3.x) is its only function newer
// than 0.3.0.
//
//   proxima_fidelity_bench [--scene bunny|engine|all] [--mode free|constrained|all]
//                          [--speeds 5,50] [--no-exact] [--json FILE]
#include <proxima/proxima.h>

#include "common/json_writer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

void check(proxResult r, const char* what) {
  if (r != PROX_SUCCESS) {
    std::fprintf(stderr, "proxima_fidelity_bench: %s: %s\n", what, proxGetLastError());
    std::exit(1);
  }
}

std::string asset(const char* name) {
  const char* env = std::getenv("PROXIMA_ASSETS");
  return std::string(env && *env ? env : PROX_SHARED_ASSETS_DIR) + "/" + name;
}


// The path as keypoints of the tool's x and y, walked at a steady speed.
struct Path {
  std::vector<double> x, y;
  double speed = 0.0;  // m/s
  double wait = 0.15;  // s still at the start, nothing within the cutoff
  double hold = 0.2;   // s at the end
  double length() const {
    double l = 0.0;
    for (std::size_t i = 1; i < x.size(); ++i) l += std::hypot(x[i] - x[i - 1], y[i] - y[i - 1]);
    return l;
  }
  double seconds() const { return wait + length() / speed + hold; }
  // The pose `t` s after the path began moving.
  void at(double t, double& px, double& py) const {
    double s = std::max(0.0, t) * speed;
    for (std::size_t i = 1; i < x.size(); ++i) {
      const double l = std::hypot(x[i] - x[i - 1], y[i] - y[i - 1]);
      if (s <= l && l > 0.0) {
        px = x[i - 1] + (x[i] - x[i - 1]) * s / l;
        py = y[i - 1] + (y[i] - y[i - 1]) * s / l;
        return;
      }
      s -= l;
    }
    px = x.back(), py = y.back();
  }
};

// The application's device: the path's pose at the haptic thread's time,
// and every wrench kept (storage reserved before the threads start).
struct HandDevice {
  const Path* path = nullptr;
  double start = 0.0;                // the threads' start (s, proxGetTime)
  std::atomic<double> moving{1e300};  // when the path began: held at its start until then
  std::vector<double> time, path_time, fx, fy, fz, px, py;
  std::atomic<std::size_t> writes{0};
  double last_x = 0.0, last_y = 0.0;  // haptic thread's own: the pose it last handed out
  static proxBool read(void* user, proxPose* pose) {
    auto* self = static_cast<HandDevice*>(user);
    double x, y;
    self->path->at(proxGetTime() - self->moving.load(std::memory_order_relaxed), x, y);
    self->last_x = x, self->last_y = y;
    *pose = {{x, y, 0.0}, {1.0, 0.0, 0.0, 0.0}};
    return 1;
  }
  static void write(void* user, const proxWrench* w) {
    auto* self = static_cast<HandDevice*>(user);
    const std::size_t n = self->writes.load(std::memory_order_relaxed);
    if (n < self->time.size()) {
      self->time[n] = proxGetTime() - self->start;
      self->path_time[n] = proxGetTime() - self->moving.load(std::memory_order_relaxed);
      self->fx[n] = w->force.x, self->fy[n] = w->force.y, self->fz[n] = w->force.z;
      self->px[n] = self->last_x, self->py[n] = self->last_y;
    }
    self->writes.store(n + 1, std::memory_order_release);
  }
};

struct SceneSpec {
  const char* name;
  std::string file;
  double scale;  // file units to metres
};

struct Figures {
  std::size_t ticks = 0, steps_over = 0, free_ticks = 0, free_nonzero = 0;
  double max_step = 0.0, max_force = 0.0, free_max = 0.0, start_max = 0.0;
  double stop_step = 0.0;  // the largest step of the fade-out after the stop
  std::size_t late = 0;    // ticks that came more than 1.5 ms after the last
  double end_gap = 0.0;    // the device pose's exact distance to A at the path's end
  double local_p99 = 0.0, local_max = 0.0;  // local tracking's update, s
  double global_p99 = 0.0;                  // the global search's, s
  // Against the exact force at each tick's device pose (replay_exact), over
  // the ticks in contact (either force non-zero) from the path's start to
  // the stop: the largest and the RMS of |F_rendered - F_exact|, N; and the
  // time shift of the exact force that best matches the rendered one (least
  // RMS difference), s, positive when the rendered force lags.
  std::size_t contact_ticks = 0;
  double error_max = 0.0, error_rms = 0.0, force_lag = std::nan("");
  // A constrained tool's: the same shift for its proxy (the flight
  // recorder's, at the reference point) against the exact one, s, and the
  // RMS distance between the two, m, unshifted.
  double proxy_lag = std::nan(""), proxy_rms = std::nan("");
};

// Per tick, a vector (a force, or a proxy's reference point).
struct Series {
  std::vector<double> x, y, z;
  explicit Series(std::size_t n = 0) : x(n, 0.0), y(n, 0.0), z(n, 0.0) {}
  double norm(std::size_t i) const { return std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]); }
  double distance(std::size_t i, const double p[3]) const {
    return std::sqrt((x[i] - p[0]) * (x[i] - p[0]) + (y[i] - p[1]) * (y[i] - p[1]) + (z[i] - p[2]) * (z[i] - p[2]));
  }
};

// Where `pose` puts the body-frame point `p`.
proxVec3 apply(const proxPose& pose, const proxVec3& p) {
  const proxQuat& q = pose.rotation;
  // v + 2 w (u x v) + 2 u x (u x v), u the quaternion's vector part.
  const double cx = q.y * p.z - q.z * p.y, cy = q.z * p.x - q.x * p.z, cz = q.x * p.y - q.y * p.x;
  const double dx = q.y * cz - q.z * cy, dy = q.z * cx - q.x * cz, dz = q.x * cy - q.y * cx;
  return {pose.position.x + p.x + 2.0 * (q.w * cx + dx), pose.position.y + p.y + 2.0 * (q.w * cy + dy),
          pose.position.z + p.z + 2.0 * (q.w * cz + dz)};
}

// The exact force at the device poses of ticks [first, stop): replayed, one
// deterministic step (proxWorld_Step) a tick, by a tool made from `def` at
// the path's start. Each step searches the pair afresh at that pose and
// gives the paper's force there; a constrained tool's proxy is moved step by
// step with its exact checks and its damper takes the rate over 1 ms. What
// an engine that kept up with the hand at every tick would render: no
// contacts a local period old, nothing faded. Also the proxy's reference
// point.
void replay_exact(proxWorldId world, proxBodyDef def, const HandDevice& d, std::size_t first, std::size_t stop,
                  Series& force, Series& proxy) {
  def.pose = {{d.px[first], d.py[first], 0.0}, {1.0, 0.0, 0.0, 0.0}};
  proxBodyId tool{};
  check(proxWorld_CreateBody(world, &def, &tool), "reference tool");
  for (std::size_t i = first; i < stop; ++i) {
    const proxPose pose{{d.px[i], d.py[i], 0.0}, {1.0, 0.0, 0.0, 0.0}};
    check(proxBody_SetPose(tool, &pose), "reference pose");
    check(proxWorld_Step(world), "reference step");
    proxWrench w{};
    check(proxBody_GetWrench(tool, &w), "reference wrench");
    force.x[i] = w.force.x, force.y[i] = w.force.y, force.z[i] = w.force.z;
    proxPose p{};
    check(proxBody_GetProxyPose(tool, &p), "reference proxy");
    const proxVec3 r = apply(p, def.referencePoint);
    proxy.x[i] = r.x, proxy.y[i] = r.y, proxy.z[i] = r.z;
  }
  check(proxBody_Destroy(tool), "reference tool");
}

// The shift of `b` that best matches `a` over the ticks `use`: the least
// RMS of |a(t) - b(t - shift)|, b linear between the ticks [first, stop),
// searched from 0 outwards by 0.25 ms to +-100 ms (a tie keeps the
// smaller shift). NaN with fewer than 50 ticks to match.
double best_shift(const std::vector<double>& time, const Series& a, const Series& b, std::size_t first,
                  std::size_t stop, const std::vector<std::size_t>& use) {
  if (use.size() < 50) return std::nan("");
  const auto b_at = [&](double t, double out[3]) {
    const auto it = std::upper_bound(time.begin() + static_cast<std::ptrdiff_t>(first),
                                     time.begin() + static_cast<std::ptrdiff_t>(stop), t);
    const std::size_t j = std::clamp<std::size_t>(static_cast<std::size_t>(it - time.begin()), first + 1, stop - 1);
    const double span = time[j] - time[j - 1];
    const double u = span > 0.0 ? std::clamp((t - time[j - 1]) / span, 0.0, 1.0) : 1.0;
    out[0] = b.x[j - 1] + u * (b.x[j] - b.x[j - 1]);
    out[1] = b.y[j - 1] + u * (b.y[j] - b.y[j - 1]);
    out[2] = b.z[j - 1] + u * (b.z[j] - b.z[j - 1]);
  };
  double best = std::nan(""), best_rms = std::nan("");
  for (int m = 0; m <= 800; ++m) {
    const double shift = 0.25e-3 * ((m + 1) / 2) * (m % 2 ? 1.0 : -1.0);
    double s2 = 0.0;
    std::size_t n = 0;
    for (const std::size_t i : use) {
      const double t = time[i] - shift;
      if (t < time[first] || t > time[stop - 1]) continue;
      double p[3];
      b_at(t, p);
      const double d = a.distance(i, p);
      s2 += d * d, ++n;
    }
    if (n == 0) continue;
    const double rms = std::sqrt(s2 / static_cast<double>(n));
    if (!(rms >= best_rms)) best_rms = rms, best = shift;  // best_rms NaN at first
  }
  return best;
}

// The rendered force and proxy against the exact ones (Figures' error and
// lags); `proxy` empty for a free tool (its proxy is the device pose).
void compare_exact(const std::vector<double>& time, const Series& rendered, const Series& exact,
                   const Series& proxy, const Series& exact_proxy, std::size_t first, std::size_t stop, Figures& f) {
  std::vector<std::size_t> contact;
  double sum = 0.0, proxy_sum = 0.0;
  for (std::size_t i = first; i < stop; ++i) {
    if (rendered.norm(i) == 0.0 && exact.norm(i) == 0.0) continue;
    contact.push_back(i);
    const double e[3] = {exact.x[i], exact.y[i], exact.z[i]};
    const double err = rendered.distance(i, e);
    f.error_max = std::max(f.error_max, err);
    sum += err * err;
    if (!proxy.x.empty()) {
      const double p[3] = {exact_proxy.x[i], exact_proxy.y[i], exact_proxy.z[i]};
      proxy_sum += proxy.distance(i, p) * proxy.distance(i, p);
    }
  }
  f.contact_ticks = contact.size();
  if (contact.empty()) return;
  const double n = static_cast<double>(contact.size());
  f.error_rms = std::sqrt(sum / n);
  f.force_lag = best_shift(time, rendered, exact, first, stop, contact);
  if (proxy.x.empty()) return;
  f.proxy_rms = std::sqrt(proxy_sum / n);
  f.proxy_lag = best_shift(time, proxy, exact_proxy, first, stop, contact);
}

// The mesh of `file` at `scale` in `world`.
proxMeshId load_scaled(proxWorldId world, const std::string& file, double scale) {
  proxMeshId loaded{};
  check(proxWorld_LoadMesh(world, file.c_str(), &loaded), file.c_str());
  if (scale == 1.0) return loaded;
  uint32_t nv = 0, nt = 0;
  proxMesh_GetTriangles(loaded, nullptr, 0, &nv, nullptr, 0, &nt);
  std::vector<double> p(3 * std::size_t{nv});
  std::vector<uint32_t> t(3 * std::size_t{nt});
  check(proxMesh_GetTriangles(loaded, p.data(), nv, &nv, t.data(), nt, &nt), "triangles");
  for (double& v : p) v *= scale;
  proxMeshDef def = proxDefaultMeshDef();
  def.positions = p.data(), def.vertexCount = nv, def.indices = t.data(), def.triangleCount = nt;
  proxMeshId mesh{};
  check(proxWorld_CreateMesh(world, &def, &mesh), "scaled mesh");
  check(proxMesh_Destroy(loaded), "destroy");
  return mesh;
}

// Where the tool's x puts it `gap` from A along +x (bisection on the exact
// distance; x0 is far enough out).
double x_at_gap(proxBodyId a, proxBodyId b, double gap, double x0) {
  double lo = 0.0, hi = x0;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    const proxPose pose{{mid, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
    check(proxBody_SetPose(b, &pose), "pose");
    double d = 0.0;
    check(proxBody_GetDistance(a, b, gap * 2.0 + 1.0, &d), "distance");
    (d < gap ? lo : hi) = mid;
  }
  return hi;
}

Figures run_one(const SceneSpec& scene, proxForcePreset preset, proxToolMode mode, double speed, bool exact_replay) {
  proxWorldDef wd = proxDefaultWorldDef();
  check(proxGetForcePreset(preset, &wd.force, &wd.cutoff), "preset");
  proxWorldId world{};
  check(proxCreateWorld(&wd, &world), "world");
  const proxMeshId mesh = load_scaled(world, scene.file, scene.scale);
  proxMeshInfo info{};
  check(proxMesh_GetInfo(mesh, &info), "info");
  const double width = info.boundsMax.x - info.boundsMin.x;
  proxBodyDef bd = proxDefaultBodyDef();
  bd.mesh = mesh;
  proxBodyId a{}, probe{};
  check(proxWorld_CreateBody(world, &bd, &a), "A");
  bd.type = PROX_BODY_MOVABLE;
  check(proxWorld_CreateBody(world, &bd, &probe), "probe");
  const double far = 2.0 * width + 0.2;
  const double cutoff = wd.cutoff;
  const double x_start = x_at_gap(a, probe, cutoff + 0.003, far);
  const double x_contact = x_at_gap(a, probe, 1e-7, far);
  const double x_free = x_at_gap(a, probe, cutoff + 0.001, far);  // beyond: nothing within the cutoff
  const double x_end = mode == PROX_TOOL_CONSTRAINED ? x_contact - 0.005 : x_at_gap(a, probe, 0.0001, far);
  // The exact distance at the path's end (0: the device pose inside A).
  const proxPose end_pose{{x_end, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  check(proxBody_SetPose(probe, &end_pose), "pose");
  double end_gap = 0.0;
  check(proxBody_GetDistance(a, probe, 1.0, &end_gap), "distance");
  check(proxBody_Destroy(probe), "probe");
  Path path;
  path.speed = speed;
  path.x = {x_start, x_end, x_end, x_end};
  path.y = {0.0, 0.0, 0.010, 0.0};

  bd.type = PROX_BODY_TOOL;
  bd.toolMode = mode;
  bd.pose = {{x_start + 0.186, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};  // created 186 mm out
  bd.referencePoint = {0.5 * (info.boundsMin.x + info.boundsMax.x), 0.5 * (info.boundsMin.y + info.boundsMax.y),
                       0.5 * (info.boundsMin.z + info.boundsMax.z)};
  proxBodyId tool{};
  check(proxWorld_CreateBody(world, &bd, &tool), "tool");
  auto device = std::make_unique<HandDevice>();
  device->path = &path;
  const std::size_t capacity = static_cast<std::size_t>(path.seconds() * 1500.0) + 2000;
  for (auto* v : {&device->time, &device->path_time, &device->fx, &device->fy, &device->fz, &device->px, &device->py})
    v->assign(capacity, 0.0);
  proxDeviceDef dd = proxDefaultDeviceDef();
  dd.readPose = &HandDevice::read;
  dd.writeWrench = &HandDevice::write;
  dd.userData = device.get();
  check(proxBody_SetDevice(tool, &dd), "device");
  proxThreadsDef td = proxDefaultThreadsDef();
  td.traceCapacity = static_cast<int32_t>(capacity);  // every tick: a constrained tool's proxy
  device->start = proxGetTime();
  check(proxWorld_StartThreads(world, &td), "start");
  // The device held still at the path's start for `wait`, and until a
  // constrained tool's proxy has joined it there (how long that takes is the
  // global search's pace: the proxy moves half the cutoff a search); then
  // closed on the device's own clock: the path walked and held.
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (proxGetTime() - device->start < path.wait) continue;
    proxPose proxy{};
    check(proxBody_GetProxyPose(tool, &proxy), "proxy");
    if (mode == PROX_TOOL_FREE || std::abs(proxy.position.x - x_start) < 1e-9) break;
    if (proxGetTime() - device->start > 60.0) {
      std::fprintf(stderr, "proxima_fidelity_bench: the proxy never joined the device\n");
      std::exit(1);
    }
  }
  device->moving = proxGetTime();
  while (proxGetTime() - device->moving.load() < path.seconds() - path.wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  proxThreadStats local{}, global{};
  check(proxWorld_GetThreadStats(world, PROX_THREAD_LOCAL, &local), "stats");
  check(proxWorld_GetThreadStats(world, PROX_THREAD_GLOBAL, &global), "stats");
  check(proxWorld_StopThreads(world), "stop");

  Figures f;
  f.end_gap = end_gap;
  f.local_p99 = local.updateP99, f.local_max = local.updateMax;
  f.global_p99 = global.updateP99;
  std::size_t& late = f.late;
  f.ticks = std::min(device->writes.load(), capacity);
  // The flight recorder's proxy, tick for tick with the device's records
  // (the haptic thread hands the device a wrench and records a sample every
  // tick, the stop's fade included).
  Series rendered(f.ticks), proxy, exact(f.ticks), exact_proxy(f.ticks);
  for (std::size_t i = 0; i < f.ticks; ++i)
    rendered.x[i] = device->fx[i], rendered.y[i] = device->fy[i], rendered.z[i] = device->fz[i];
  if (mode == PROX_TOOL_CONSTRAINED) {
    std::vector<proxHapticSample> trace(capacity);
    int32_t count = 0;
    check(proxBody_GetHapticTrace(tool, trace.data(), static_cast<int32_t>(capacity), &count), "trace");
    if (static_cast<std::size_t>(count) == f.ticks && count > 0 && trace[0].tick == 0) {
      proxy = Series(f.ticks);
      for (std::size_t i = 0; i < f.ticks; ++i) {
        const proxVec3 r = apply(trace[i].proxyPose, bd.referencePoint);
        proxy.x[i] = r.x, proxy.y[i] = r.y, proxy.z[i] = r.z;
      }
    } else {  // more ticks than the storage reserved: no proxy figures
      std::fprintf(stderr, "proxima_fidelity_bench: %d ticks recorded for %zu written\n", count, f.ticks);
    }
  }
  // The ticks from the path's start to the stop, replayed for the exact
  // force (the threaded tool gone: the world's only tool).
  const double moving_seconds = path.seconds() - path.wait;
  std::size_t first = 0, stop = 0;
  while (first < f.ticks && device->path_time[first] < 0.0) ++first;
  for (stop = first; stop < f.ticks && device->path_time[stop] <= moving_seconds;) ++stop;
  check(proxBody_Destroy(tool), "tool");
  if (exact_replay && stop > first) {
    replay_exact(world, bd, *device, first, stop, exact, exact_proxy);
    compare_exact(device->time, rendered, exact, proxy, exact_proxy, first, stop, f);
  }
  check(proxWorld_Destroy(world), "destroy");
  double last[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < f.ticks; ++i) {
    const double F[3] = {device->fx[i], device->fy[i], device->fz[i]};
    const double mag = std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    // A tick the scheduler held up covers more of the motion: its step is
    // taken per millisecond of it, as a tick on time would have seen it.
    const double gap = i > 0 ? device->time[i] - device->time[i - 1] : 0.001;
    late += gap > 0.0015;
    const double step = std::sqrt((F[0] - last[0]) * (F[0] - last[0]) + (F[1] - last[1]) * (F[1] - last[1]) +
                                  (F[2] - last[2]) * (F[2] - last[2])) *
                        (0.001 / std::max(gap, 0.001));
    std::copy(F, F + 3, last);
    f.max_force = std::max(f.max_force, mag);
    // The fade-out after proxWorld_StopThreads is the safety gate's (its
    // rate limit), counted apart.
    if (device->path_time[i] > moving_seconds) {
      f.stop_step = std::max(f.stop_step, step);
      continue;
    }
    f.max_step = std::max(f.max_step, step);
    f.steps_over += step > 0.05;
    // Free air: the device (and with it, at this speed, its proxy) farther
    // than the cutoff and a millimetre from A, on the way in.
    const bool approaching = device->path_time[i] * speed < x_start - x_end;
    if (approaching && device->px[i] > x_free) {
      ++f.free_ticks;
      f.free_nonzero += mag != 0.0;
      f.free_max = std::max(f.free_max, mag);
    }
    // The first 100 ms of the threads, the device still, nothing in range.
    if (device->time[i] <= 0.1) f.start_max = std::max(f.start_max, mag);
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  std::string which = "all", json_path, which_mode = "all";
  std::vector<double> speeds = {0.005, 0.05};
  bool exact_replay = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--scene" && i + 1 < argc) {
      which = argv[++i];
    } else if (a == "--speeds" && i + 1 < argc) {
      speeds.clear();
      for (const char* p = argv[++i]; *p;) {
        char* end = nullptr;
        speeds.push_back(std::strtod(p, &end) * 1e-3);
        p = *end == ',' ? end + 1 : end;
        if (end == p && *p) break;
      }
    } else if (a == "--json" && i + 1 < argc) {
      json_path = argv[++i];
    } else if (a == "--mode" && i + 1 < argc) {
      which_mode = argv[++i];
    } else if (a == "--no-exact") {
      exact_replay = false;
    } else {
      std::fprintf(stderr,
                   "usage: proxima_fidelity_bench [--scene bunny|engine|all] [--mode free|constrained|all] "
                   "[--speeds MM/S,...] [--no-exact] [--json FILE]\n");
      return 2;
    }
  }
  std::vector<SceneSpec> scenes;
  if (which == "all" || which == "bunny") scenes.push_back({"bunny", asset("bunny.obj"), 1.0});
  if (which == "all" || which == "engine") scenes.push_back({"engine", asset("gltf/2CylinderEngine.glb"), 0.001});
  const proxForcePreset presets[2] = {PROX_FORCE_PRESET_SOFT, PROX_FORCE_PRESET_HARD};
  const proxToolMode modes[2] = {PROX_TOOL_FREE, PROX_TOOL_CONSTRAINED};
  prox::JsonWriter j;
  j.begin_array();
  std::printf("%-7s %-5s %-12s %6s %7s %10s %10s %8s %11s %11s %11s %11s %5s %10s %16s %10s %7s %9s %9s %8s %12s %12s\n", "scene", "force", "mode", "mm/s",
              "ticks", "max |F| N", "max step N", "> 0.05", "free ticks", "free max N", "start max N", "stop step N", "late", "end gap mm", "local p99/max ms", "global p99",
              "contact", "err max N", "err rms N", "F lag ms", "proxy lag ms", "proxy rms mm");
  for (const SceneSpec& scene : scenes)
    for (const proxForcePreset preset : presets)
      for (const proxToolMode mode : modes)
        for (const double speed : speeds) {
          if (which_mode != "all" && which_mode != (mode == PROX_TOOL_FREE ? "free" : "constrained")) continue;
          const Figures f = run_one(scene, preset, mode, speed, exact_replay);
          const char* force = preset == PROX_FORCE_PRESET_SOFT ? "soft" : "hard";
          const char* tool = mode == PROX_TOOL_FREE ? "free" : "constrained";
          std::printf("%-7s %-5s %-12s %6.0f %7zu %10.4f %10.4f %8zu %11zu %11.3g %11.3g %11.4f %5zu %10.3f %8.2f/%7.1f "
                      "%10.2f %7zu %9.4f %9.4f %8.2f %12.2f %12.4f\n",
                      scene.name, force, tool, speed * 1e3, f.ticks, f.max_force, f.max_step, f.steps_over,
                      f.free_ticks, f.free_max, f.start_max, f.stop_step, f.late, f.end_gap * 1e3,
                      f.local_p99 * 1e3, f.local_max * 1e3, f.global_p99 * 1e3, f.contact_ticks, f.error_max, f.error_rms,
                      f.force_lag * 1e3, f.proxy_lag * 1e3, f.proxy_rms * 1e3);
          std::fflush(stdout);
          j.begin_object();
          j.key("scene").value(scene.name).key("force").value(force).key("mode").value(tool);
          j.key("speed_mm_s").value(speed * 1e3).key("ticks").value(static_cast<long long>(f.ticks));
          j.key("max_force").value(f.max_force).key("max_step").value(f.max_step);
          j.key("steps_over_0_05").value(static_cast<long long>(f.steps_over));
          j.key("free_ticks").value(static_cast<long long>(f.free_ticks));
          j.key("free_nonzero").value(static_cast<long long>(f.free_nonzero));
          j.key("free_max").value(f.free_max).key("start_max").value(f.start_max);
          j.key("local_update_p99").value(f.local_p99).key("local_update_max").value(f.local_max);
          j.key("global_update_p99").value(f.global_p99);
          j.key("end_gap").value(f.end_gap).key("stop_step").value(f.stop_step).key("late_ticks").value(static_cast<long long>(f.late));
          j.key("contact_ticks").value(static_cast<long long>(f.contact_ticks));
          j.key("error_max").value(f.error_max).key("error_rms").value(f.error_rms);
          j.key("force_lag").value(f.force_lag).key("proxy_lag").value(f.proxy_lag).key("proxy_rms").value(f.proxy_rms);
          j.end_object();
        }
  j.end_array();
  if (!json_path.empty()) {
    std::FILE* out = std::fopen(json_path.c_str(), "w");
    if (!out) return 1;
    std::fputs((j.str() + "\n").c_str(), out);
    std::fclose(out);
  }
  return 0;
}
