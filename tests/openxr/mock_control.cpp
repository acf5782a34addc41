// The mock runtime's scripted grip and the test's control panel
// (mock_control.h).
#include "mock_state.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace prox::mock_xr {

// The default motion (mock_control.h) or the script, at a time.
Pose grip_at(XrTime t, V* velocity, V* angular) {
  *velocity = {0, 0, 0};
  *angular = {0, 0, 0};
  if (g.script.empty()) {
    if (g.first_located == 0) g.first_located = t;
    const double s = double(std::max<XrTime>(0, t - g.first_located) % 4000000000LL) * 1e-9,
                 w = 2 * M_PI / 4.0;
    const double z = -0.3 - 0.075 * (1 - std::cos(w * s));
    velocity->z = -0.075 * w * std::sin(w * s);
    return {{1, 0, 0, 0}, {0.1, 1.2, z}};
  }
  const std::vector<ProxMockXrKey>& k = g.script;
  if (t <= k.front().time) return of(k.front().pose);
  if (t >= k.back().time) return of(k.back().pose);
  std::size_t i = 0;
  while (k[i + 1].time < t) ++i;
  const Pose a = of(k[i].pose), b = of(k[i + 1].pose);
  const double dt = double(k[i + 1].time - k[i].time) * 1e-9, f = double(t - k[i].time) * 1e-9 / dt;
  *velocity = {(b.p.x - a.p.x) / dt, (b.p.y - a.p.y) / dt, (b.p.z - a.p.z) / dt};
  Q d = mul(b.q, conj(a.q));  // world-frame rotation from a to b
  if (d.w < 0) d = {-d.w, -d.x, -d.y, -d.z};
  const double sn = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (sn > 1e-12) {
    const double angle = 2 * std::atan2(sn, d.w) / dt;
    *angular = {d.x / sn * angle, d.y / sn * angle, d.z / sn * angle};
  }
  Pose p;
  p.q = slerp(a.q, b.q, f);
  p.p = {a.p.x + (b.p.x - a.p.x) * f, a.p.y + (b.p.y - a.p.y) * f, a.p.z + (b.p.z - a.p.z) * f};
  return p;
}

// ---- habits ---------------------------------------------------------------------------
namespace {

std::atomic<std::uint32_t> g_panel_habits{0};

}  // namespace

std::uint32_t habits_for_new_instance() {
  std::uint32_t h = g_panel_habits.load();
  if (const char* env = std::getenv("PROX_MOCK_XR_HABITS")) {
    static const struct {
      const char* name;
      std::uint32_t bit;
    } kNames[] = {{"zero_display_time", PROX_MOCK_XR_HABIT_ZERO_DISPLAY_TIME},
                  {"no_timespec", PROX_MOCK_XR_HABIT_NO_TIMESPEC},
                  {"stays_ready", PROX_MOCK_XR_HABIT_STAYS_READY},
                  {"answers_unfocused", PROX_MOCK_XR_HABIT_ANSWERS_UNFOCUSED}};
    for (const auto& n : kNames)
      if (std::strstr(env, n.name)) h |= n.bit;
  }
  return h;
}

// ---- the control panel ---------------------------------------------------------------
namespace {

void set_script(const ProxMockXrKey* keys, int32_t count) {
  std::lock_guard<std::mutex> lock(g.mutex);
  g.script.assign(keys, keys + std::min(count, kMaxKeys));
}
void set_tracked(int32_t tracked) {
  std::lock_guard<std::mutex> lock(g.mutex);
  g.tracked = tracked != 0;
}
void set_focused(int32_t on) {
  std::lock_guard<std::mutex> lock(g.mutex);
  if (on && g.state == XR_SESSION_STATE_VISIBLE) set_state(XR_SESSION_STATE_FOCUSED);
  if (!on && g.state == XR_SESSION_STATE_FOCUSED) set_state(XR_SESSION_STATE_VISIBLE);
}
int32_t vibrations(ProxMockXrVibration* out, int32_t first, int32_t capacity) {
  std::lock_guard<std::mutex> lock(g.mutex);
  for (int32_t i = 0; i < capacity && first + i < int32_t(g.log.size()); ++i)
    out[i] = g.log[std::size_t(first + i)];
  return int32_t(g.log.size());
}
void set_habits(uint32_t habits) { g_panel_habits.store(habits); }
uint64_t wait_calls() { return g_waits.load(); }
uint64_t sync_calls() { return g_syncs.load(); }
uint64_t locate_calls() { return g_locates.load(); }
int32_t max_concurrent() { return g_max_inside.load(); }

const ProxMockXrControl kControl = {set_script,   set_tracked,    set_focused, vibrations, locate_calls,
                                    max_concurrent, now_ns,         set_habits,  wait_calls, sync_calls};
}  // namespace

const ProxMockXrControl* get_control() { return &kControl; }

}  // namespace prox::mock_xr

// The panel's plain exports (mock_control.h), for the bindings' tests.
#define PROX_MOCK_XR_EXPORT extern "C" __attribute__((visibility("default")))
PROX_MOCK_XR_EXPORT void proxMockXr_SetScript(const ProxMockXrKey* keys, int32_t count) {
  prox::mock_xr::get_control()->setScript(keys, count);
}
PROX_MOCK_XR_EXPORT void proxMockXr_SetTracked(int32_t tracked) {
  prox::mock_xr::get_control()->setTracked(tracked);
}
PROX_MOCK_XR_EXPORT void proxMockXr_SetFocused(int32_t focused) {
  prox::mock_xr::get_control()->setFocused(focused);
}
PROX_MOCK_XR_EXPORT int32_t proxMockXr_Vibrations(ProxMockXrVibration* out, int32_t first, int32_t capacity) {
  return prox::mock_xr::get_control()->vibrations(out, first, capacity);
}
PROX_MOCK_XR_EXPORT uint64_t proxMockXr_LocateCalls(void) { return prox::mock_xr::get_control()->locateCalls(); }
PROX_MOCK_XR_EXPORT XrTime proxMockXr_Now(void) { return prox::mock_xr::get_control()->now(); }
PROX_MOCK_XR_EXPORT void proxMockXr_SetHabits(uint32_t habits) { prox::mock_xr::get_control()->setHabits(habits); }
