// Worlds: create, destroy, the deterministic step and its statistics.
#include "capi/common.h"
#include "capi/device_table.h"

using namespace prox;
using namespace prox::capi;

extern "C" {

proxWorldDef proxDefaultWorldDef(void) {
  const ForceSettings f = hard_force_settings();
  proxWorldDef d{};
  d.apiVersion = PROX_API_VERSION;
  d.method = PROX_METHOD_PRECISE;
  d.cutoff = f.cutoff;
  d.force = {PROX_FORCE_EXPONENTIAL, f.max_force, f.max_torque, f.safety_distance, f.decay_length};
  d.internalValue = kDefCookie;
  d.workerCount = 1;
  return d;
}

namespace {

void destroy_world(proxWorldId world) {
  world_of(world);  // validates id and thread
  std::unique_ptr<runtime::World> doomed;
  {
    std::lock_guard<std::mutex> lock(g_worlds_mutex);
    doomed = std::move(g_worlds[world.index1 - 1].world);
  }
  // No device callback runs once the threads stop; then no other thread
  // may still hold one of the world's streamed devices.
  doomed->stop_threads();
  release_devices(world);
}

}  // namespace

proxResult proxCreateWorld(const proxWorldDef* def, proxWorldId* world) {
  return guard("proxCreateWorld", [&] {
    need(def, "def");
    need(world, "world");
    *world = proxWorldId{};
    need_def(*def, "proxDefaultWorldDef");
    const int32_t method = enum_value(def->method);
    if (method != PROX_METHOD_PRECISE && method != PROX_METHOD_ORIGINAL && method != PROX_METHOD_REFERENCE)
      fail(PROX_ERROR_INVALID_ARGUMENT, "def->method is not a proxMethod");
    need_positive(def->cutoff, "def->cutoff");
    if (def->workerCount < 1 || def->workerCount > 256)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "def->workerCount is " + std::to_string(def->workerCount) + "; it must be in [1, 256]");
    runtime::WorldSettings s;
    s.method = method == PROX_METHOD_ORIGINAL    ? Method::Original
               : method == PROX_METHOD_REFERENCE ? Method::Reference
                                                 : Method::Precise;
    s.force = to_force(def->force, def->cutoff);
    s.workers = static_cast<unsigned>(def->workerCount);
    auto w = std::make_unique<runtime::World>(s);
    std::lock_guard<std::mutex> lock(g_worlds_mutex);
    uint32_t i = 0;
    while (i < g_worlds.size() && g_worlds[i].world) ++i;
    if (i == g_worlds.size()) g_worlds.emplace_back();
    g_worlds[i].generation += 1;
    g_worlds[i].world = std::move(w);
    g_worlds[i].owner = std::this_thread::get_id();
    *world = {i + 1, g_worlds[i].generation};
  });
}

proxResult proxWorld_Destroy(proxWorldId world) {
  return guard("proxWorld_Destroy", [&] { destroy_world(world); });
}

proxResult proxDestroyWorld(proxWorldId world) {
  return guard("proxDestroyWorld", [&] { destroy_world(world); });
}

proxBool proxWorld_IsValid(proxWorldId world) {
  if (world.index1 == 0) return 0;
  std::lock_guard<std::mutex> lock(g_worlds_mutex);
  const uint32_t i = world.index1 - 1;
  return i < g_worlds.size() && g_worlds[i].generation == world.generation && g_worlds[i].world ? 1 : 0;
}

proxResult proxWorld_Step(proxWorldId world) {
  return guard("proxWorld_Step", [&] {
    runtime::World& w = world_of(world);
    need_stopped(w);
    w.step();
  });
}

proxResult proxWorld_GetStats(proxWorldId world, proxWorldStats* stats) {
  return guard("proxWorld_GetStats", [&] {
    need(stats, "stats");
    const runtime::World& w = world_of(world);
    const runtime::StepStats s = w.stats();
    *stats = {w.body_count(),   w.tool_count(), s.pairs_in_range,
              s.pairs_searched, s.contacts,     static_cast<int32_t>(s.candidates),
              s.seconds};
  });
}

}  // extern "C"
