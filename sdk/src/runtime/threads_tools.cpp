// The tools the runtime's threads drive (threads.h), and the game thread's
// side of them: tools made and destroyed while the threads run, published
// as immutable sets that each thread takes at the start of an iteration.
// A set or a tool is freed by the game thread once every thread has said it
// works with a newer set (an epoch scheme: the haptic loop never waits for,
// allocates or frees anything of it).
#include "runtime/threads.h"

#include <algorithm>
#include <chrono>
#include <thread>

namespace prox::runtime {
namespace {


}  // namespace

std::unique_ptr<Threads::Tool> Threads::make_tool(std::uint32_t i) {
  const World::ToolStart b = world_.tool_start(i);
  auto tool = std::make_unique<Tool>();
  tool->body = i;
  tool->device = b.device;
  tool->reference_local = b.reference_point;
  tool->radius = b.radius;
  const PoseSample start{b.tool.mode == coupling::ToolMode::Constrained ? b.device_pose : b.pose, 0.0};
  tool->pose.store(start);
  tool->game_pose.store(start);
  tool->constrained = b.tool.mode == coupling::ToolMode::Constrained;
  tool->coupling = b.tool.coupling;
  tool->proxy.store({b.pose, 0.0});
  tool->rendered.store({b.pose, 0.0});
  tool->proxy_state.pose = b.pose;
  tool->anchor = b.pose;
  tool->wrench.store({b.wrench});
  tool->contacts = b.contacts;
  // The haptic loop's snapshots never grow once the threads run. Clamped
  // to the range check() accepts, for a Threads constructed without asking
  // it first (World::start_threads asks).
  const auto capacity = static_cast<std::size_t>(std::clamp(settings_.max_contacts, 1, kMaxContactsPerTool));
  for (int k = 0; k < 3; ++k) {
    tool->snapshots.buffer(k).contacts.reserve(capacity);
    if (tool->constrained) tool->snapshots.buffer(k).constraints.reserve(capacity);
  }
  const DeviceLimits limits = b.device.attached() ? b.device->limits() : DeviceLimits{};
  tool->renderer = HapticRenderer({world_.settings().force, tool->constrained, tool->coupling,
                                   tool->reference_local, tool->radius, capacity, b.pose, limits});
  if (settings_.trace_capacity > 0)
    tool->trace = std::make_unique<TraceRing<TraceSample>>(
        static_cast<std::size_t>(std::min(settings_.trace_capacity, kMaxTraceCapacity)));
  tool->filter = SafetyFilter({world_.settings().force.max_force, world_.settings().force.max_torque,
                               settings_.max_force_rate, settings_.max_torque_rate});
  return tool;
}

void Threads::publish(std::unique_ptr<ToolSet> next) {
  std::sort(next->tools.begin(), next->tools.end(), [](const Tool* a, const Tool* b) { return a->body < b->body; });
  next->of_body.assign(world_.body_slots(), -1);
  for (std::size_t k = 0; k < next->tools.size(); ++k)
    next->of_body[next->tools[k]->body] = static_cast<int>(k);
  next->version = sets_.empty() ? 1 : sets_.back()->version + 1;
  set_.store(next.get(), std::memory_order_release);
  sets_.push_back(std::move(next));
}

const Threads::ToolSet& Threads::acquire(Role role) {
  const ToolSet* set = set_.load(std::memory_order_acquire);
  seen_[int(role)].store(set->version, std::memory_order_release);
  return *set;
}

void Threads::reclaim() {
  // Before the threads start, and after they stop, nothing else reads.
  std::uint64_t oldest = sets_.back()->version;
  if (started_)
    for (const auto& s : seen_) oldest = std::min(oldest, s.load(std::memory_order_acquire));
  // A set older than every thread's is seen by none.
  sets_.erase(std::remove_if(sets_.begin(), sets_.end() - 1,
                             [oldest](const std::unique_ptr<ToolSet>& s) { return s->version < oldest; }),
              sets_.end() - 1);
  retired_.erase(std::remove_if(retired_.begin(), retired_.end(),
                                [oldest](const Retired& r) { return r.after <= oldest; }),
                 retired_.end());
}

const Threads::Tool* Threads::tool_of(std::uint32_t body) const {
  const ToolSet& set = current();
  if (body >= set.of_body.size() || set.of_body[body] < 0) return nullptr;
  return set.tools[std::size_t(set.of_body[body])];
}

void Threads::add_tool(std::uint32_t body) {
  reclaim();
  tools_.push_back(make_tool(body));
  auto next = std::make_unique<ToolSet>();
  next->tools = current().tools;
  next->tools.push_back(tools_.back().get());
  publish(std::move(next));
}

void Threads::remove_tool(std::uint32_t body) {
  const auto owned = std::find_if(tools_.begin(), tools_.end(),
                                  [body](const std::unique_ptr<Tool>& t) { return t->body == body; });
  if (owned == tools_.end()) return;
  Tool& tool = **owned;
  // The haptic loop fades the device out over its next ticks; wait for its
  // last zero, closing the loop on what it says rather than on a time (a
  // stalled haptic loop is given a second).
  tool.retiring.store(1, std::memory_order_release);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (started_ && tool.retiring.load(std::memory_order_acquire) != 2 && !stop_.load() &&
         std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  auto next = std::make_unique<ToolSet>();
  for (Tool* t : current().tools)
    if (t != &tool) next->tools.push_back(t);
  publish(std::move(next));
  retired_.push_back({std::move(*owned), current().version});
  tools_.erase(owned);
  reclaim();
}

// ---- the game thread's side --------------------------------------------------------

void Threads::set_tool_pose(std::uint32_t body, const Pose& pose) {
  if (const Tool* tool = tool_of(body)) const_cast<Tool*>(tool)->game_pose.store({pose, now()});
}

Pose Threads::tool_pose(std::uint32_t body) const { return tool_of(body)->pose.load().pose; }

Pose Threads::proxy_pose(std::uint32_t body) const {
  const Tool& tool = *tool_of(body);
  return tool.constrained ? tool.rendered.load().pose : tool.pose.load().pose;
}

Wrench Threads::wrench(std::uint32_t body) const { return tool_of(body)->wrench.load().wrench; }

void Threads::contacts(std::uint32_t body, std::vector<Contact>& out) const {
  const Tool* tool = tool_of(body);
  std::lock_guard<std::mutex> lock(results_mutex_);
  out = tool->contacts;
}

std::size_t Threads::trace(std::uint32_t body, TraceSample* out, std::size_t max) const {
  const Tool* tool = tool_of(body);
  if (!tool || !tool->trace) return 0;
  return tool->trace->copy_newest(out, max);
}

}  // namespace prox::runtime
