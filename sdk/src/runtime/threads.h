// The runtime's three threads beside the caller's (paper section 5,
// docs/threading.md):
//
//   haptic  (1 kHz): reads each tool's pose from its device, re-evaluates the
//            latest tracked contacts at that pose, passes the wrench through
//            the safety gate and writes it to the device. No lock, no
//            allocation, no wait.
//   local   (1 kHz): tracks every tool's LMD pairs to the tool's latest pose
//            and publishes them to the haptic loop; adopts the global
//            search's results as they come.
//   global  (back to back): broadphase, global search and its reduction for
//            every tool against the bodies in range.
//
// Handoffs: tool poses go out of the haptic loop through seqlocks; global
// results to the local thread and contact snapshots to the haptic loop
// through triple buffers. The game thread's pose updates and its reading of
// the results meet the other threads under mutexes, never the haptic loop.
#pragma once

#include "runtime/handoff.h"
#include "runtime/haptic_render.h"
#include "runtime/haptic_trace.h"
#include "runtime/haptic.h"
#include "runtime/loop_stats.h"
#include "runtime/world.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace prox::runtime {

enum class Role { Haptic = 0, Local = 1, Global = 2 };

inline constexpr int kMaxContactsPerTool = 1 << 20;  // ThreadSettings::max_contacts
inline constexpr int kMaxTraceCapacity = 1 << 20;    // ThreadSettings::trace_capacity: 17 min at 1 kHz, 216 MiB

// How the haptic loop waits for its next period's absolute deadline.
enum class HapticTiming {
  Auto,   // Spin when the haptic thread got a real-time priority or a core of its own, else Sleep
  Spin,   // sleep to spin_margin before it, then spin on the clock: on time, at a cost in CPU
  Sleep,  // sleep to the deadline: no CPU between ticks, late by the scheduler's wake-up
};

struct ThreadSettings {
  double haptic_rate = 1000.0;  // Hz (> 0)
  double local_rate = 1000.0;   // Hz; 0: back to back
  double global_rate = 0.0;     // Hz; 0: back to back (it idles while nothing moves)
  int cores[3] = {-1, -1, -1};  // per Role: the core to pin the thread to; -1: not pinned
  double stale_after = 0.05;    // s: contacts older than this fade the force out
  // The largest rates of change the safety gate lets through (N/s, N m/s).
  double max_force_rate = 300.0;
  double max_torque_rate = 30.0;
  // Contacts tracked at a tool pose farther than this from the current one
  // (any point of the tool within its bounds; 0: the world's cutoff) are not
  // trusted: the force fades out until tracking catches up.
  double trust_distance = 0.0;
  int max_contacts = 1024;  // per tool handed to the haptic loop (the closest ones)
  // Spinning without a real-time priority or a core of its own makes the
  // loop later, not earlier, on a busy machine: the scheduler takes the
  // spinning thread off its core (docs/threading.md).
  HapticTiming haptic_timing = HapticTiming::Auto;
  double spin_margin = 0.0002;  // s: Spin's sleep ends this long before the deadline
  // SCHED_FIFO priority (1-99) asked for the haptic and local threads; 0:
  // none. Refused (no privilege) is reported in the stats, never fatal.
  int realtime_priority[2] = {0, 0};
  // mlockall(MCL_CURRENT) once the threads run, so no page the haptic loop
  // touches can be paged out (process-wide; reported, never fatal).
  bool lock_memory = false;
  // The flight recorder: the last this many haptic ticks of each tool
  // (haptic_trace.h), reserved when the threads are made; 0: off.
  int trace_capacity = 0;
  // Threads the global search splits each pair's search over, itself
  // included, in [1, 256].
  int global_workers = 1;
};

// Cores for the haptic and local threads on a machine with at least four
// the process may use: the last two, one each (the paper's layout), and the
// global search unpinned; -1 for all three below that.
void default_cores(int cores[3]);

// What the system granted a thread.
struct ThreadGrant {
  int pinned_core = -1;
  int realtime_priority = 0;  // SCHED_FIFO priority granted; 0: none asked or refused
  int realtime_error = 0;     // errno of a refused request (EPERM: no privilege)
};

// Counters of the haptic loop's safety decisions, over all tools.
struct HapticCounters {
  std::uint64_t invalid_poses = 0;     // the device gave no pose, or a non-finite one
  std::uint64_t stale_ticks = 0;       // contacts too old: faded out
  std::uint64_t untrusted_ticks = 0;   // tool too far from where contacts were tracked
  std::uint64_t limited_ticks = 0;     // the gate changed the wrench (clip or rate)
  std::uint64_t torn_snapshots = 0;    // a snapshot failed its checksum (never expected)
  std::uint64_t dropped_contacts = 0;  // beyond max_contacts, in the last snapshots
};

class Threads {
 public:
  Threads(World& world, const ThreadSettings& settings);
  ~Threads();
  Threads(const Threads&) = delete;
  Threads& operator=(const Threads&) = delete;

  // Whether the settings can start threads (false, with `status` naming
  // what is wrong). World::start_threads asks before constructing, so that
  // refused settings reserve no snapshot storage.
  static bool check(const ThreadSettings& settings, Status& status);
  // Checks the settings and starts the threads (false, with `status`).
  bool start(Status& status);
  // Fades every device's wrench out, then stops and joins the threads.
  void stop();
  bool running() const { return started_; }

  // Game thread: tools made and destroyed while the threads run
  // (docs/dynamic-scenes.md). add_tool starts driving the world's tool
  // `body` (made, with its device, since the threads started); remove_tool
  // fades its device's wrench out and waits until the haptic loop has
  // written its last zero, so no callback of the device runs after it
  // returns (unless the haptic loop is stalled past a second: then it gives
  // up waiting). Either one publishes a new set of tools; what no thread can
  // still see is freed by the game thread, never by the others.
  void add_tool(std::uint32_t body);
  void remove_tool(std::uint32_t body);

  // Game thread.
  void set_tool_pose(std::uint32_t body, const Pose& pose);
  Pose tool_pose(std::uint32_t body) const;
  // A constrained tool's proxy as the haptic loop last moved it; a free
  // tool's pose.
  Pose proxy_pose(std::uint32_t body) const;
  Wrench wrench(std::uint32_t body) const;
  void contacts(std::uint32_t body, std::vector<Contact>& out) const;
  StepStats step_stats() const;

  // Game thread. The tool's newest recorded ticks, at most `max`, oldest
  // first; 0 when the recorder is off.
  std::size_t trace(std::uint32_t body, TraceSample* out, std::size_t max) const;
  LoopSummary loop_summary(Role role) const { return loop_stats_[int(role)].summary(); }
  HapticCounters haptic_counters() const;
  int pinned_core(Role role) const { return pinned_[int(role)].load(std::memory_order_relaxed); }
  ThreadGrant grant(Role role) const;
  // mlockall's outcome: locked, or the errno that refused it (0: not asked).
  bool memory_locked() const { return memory_locked_.load(std::memory_order_relaxed); }
  // Spin or Sleep, as the haptic thread resolved Auto when it started.
  HapticTiming haptic_timing() const { return timing_.load(std::memory_order_relaxed); }
  int memory_lock_error() const { return memory_lock_error_.load(std::memory_order_relaxed); }
  // How the haptic thread's sleeps wait (platform::SleepTimer's values), as
  // it found when it started.
  int sleep_timer() const { return sleep_timer_.load(std::memory_order_relaxed); }
  // CPU seconds a running thread has used so far (its own clock); -1 when
  // the system cannot tell. For benchmarks: what a timing mode costs.
  double cpu_seconds(Role role) const;
  // The periods of the last LoopStats::kWindow iterations, for benchmarks.
  std::vector<double> periods(Role role) const { return loop_stats_[int(role)].periods(); }

  // Fault injection, for tests: a stalled thread does nothing until released.
  void stall(Role role, bool stalled) { stalled_[int(role)].store(stalled, std::memory_order_relaxed); }

 private:
  // Both pose seqlocks start with the body's pose, so a sample is always valid.
  struct PoseSample {
    Pose pose;
    double time = 0.0;  // steady-clock seconds when read
  };
  struct WrenchSample {
    Wrench wrench;
  };
  struct GlobalPair {
    std::uint32_t other = 0, other_generation = 0;
    Pose other_pose;
    std::vector<LmdPair> lmds;
  };
  struct GlobalResult {
    std::vector<GlobalPair> pairs;
    std::uint64_t view = 0;  // the scene version searched
    Pose tool_pose;  // searched at
    std::uint64_t sequence = 0;
  };
  struct LocalPair {
    std::uint32_t other = 0, other_generation = 0;
    Pose other_pose;
    LocalTracker tracker;
    std::vector<LmdPair> lmds;
  };
  struct Tool {
    std::uint32_t body = 0;
    Device device;
    Vec3 reference_local{0.0};
    double radius = 0.0;                          // of the tool's bounds about the reference point, as made
    SeqLock<PoseSample> pose;                     // haptic -> local, global, game
    SeqLock<PoseSample> game_pose;                // game -> haptic, for tools no device holds
    SeqLock<WrenchSample> wrench;                 // haptic -> game
    TripleBuffer<ContactSnapshot> snapshots;      // local -> haptic
    TripleBuffer<GlobalResult> global;            // global -> local
    SafetyFilter filter;                          // haptic's own
    std::vector<LocalPair> local_pairs;           // local's own
    std::uint64_t published = 0;                  // local's own: snapshots so far
    std::vector<std::uint32_t> published_others;  // global's own: the pairs it last handed over
    // Local tracking's updates that dropped LMDs (out of range, or merged
    // into another) other than the one adopting a global result: only a
    // global result brings those back, even where the pose the search sees
    // has not changed since its last one (the tool went and came back).
    std::atomic<std::uint64_t> losses{0};         // local -> global
    std::uint64_t published_losses = 0;           // global's own: `losses` at its last hand-over
    std::vector<Contact> contacts;                // local -> game, under results_mutex_
    // Constrained tools (docs/coupling.md): `pose` is the device's, the
    // proxy is local tracking's and reaches the haptic loop in the snapshot.
    bool constrained = false;
    coupling::CouplingSettings coupling;
    SeqLock<PoseSample> proxy;                  // local -> global: the verified proxy
    coupling::ProxyState proxy_state;           // local's own
    Pose anchor;                                // local's own: where the adopted global result searched
    bool anchored = false;                      // local's own: a global result adopted
    std::uint64_t published_version = 0;        // global's own: the tool pose version last handed over
    std::uint64_t published_view = 0;           // global's own: the scene version last handed over
    std::vector<coupling::Obstacle> obstacles;  // local's own
    HapticRenderer renderer;                    // haptic's own
    SeqLock<PoseSample> rendered;               // haptic -> game: the proxy at the haptic rate
    double closest = kNoContact;                // haptic's own: the last trusted tick's, for the device
    std::unique_ptr<TraceRing<TraceSample>> trace;  // haptic -> any; null when the recorder is off
    // Being removed (remove_tool): 0 live; 1 the game thread asks the haptic
    // loop to fade its device out; 2 the haptic loop has written the last
    // zero and calls the device no more.
    std::atomic<int> retiring{0};
    // The global search's own: the tool pose it last searched at, that
    // pose's version, and the tool's mesh shape it searched.
    Pose searched_pose;
    std::uint64_t searched_version = 0, searched_shape = 0;
  };
  // The tools the threads drive: immutable once published. Each thread
  // takes the newest at the start of an iteration and says so in seen_.
  struct ToolSet {
    std::vector<Tool*> tools;
    std::vector<int> of_body;  // body slot -> index in tools, or -1
    std::uint64_t version = 0;
  };

  // A tool for the world's body `body`, its storage reserved: game thread.
  std::unique_ptr<Tool> make_tool(std::uint32_t body);
  // Publishes `next` as the newest set (game thread).
  void publish(std::unique_ptr<ToolSet> next);
  // Frees the sets and tools no thread can still see (game thread).
  void reclaim();
  // The newest set, for `role`'s iteration; said in seen_ (that role's thread).
  const ToolSet& acquire(Role role);
  // The newest set, on the game thread, which publishes them.
  const ToolSet& current() const { return *sets_.back(); }
  const Tool* tool_of(std::uint32_t body) const;
  // The fade of the haptic loop's last ticks for a tool: one step towards a
  // zero wrench; true once it is zero (haptic thread).
  bool fade_step(Tool& tool, double dt);

  void haptic_main();
  void local_main();
  void global_main();
  void haptic_tick(Tool& tool, double now, double dt);
  // Records a tick in the tool's flight recorder, if it has one.
  void record(Tool& tool, double now, const Pose& device, const Pose& proxy, const Wrench& w, double closest,
              std::uint32_t contacts, std::uint32_t flags);
  void track(Tool& tool, const ToolSet& set, std::vector<const LmdPair*>& scratch);
  // A new version of the scene on the local thread: pairs with bodies that
  // are gone are dropped at once (their contacts fade from the force as any
  // lost contact does); the others are tracked on their meshes' new shapes.
  void adopt_view(Tool& tool);
  // A constrained tool's proxy towards the device, on the local thread.
  void move_proxy(Tool& tool, const PoseSample& device);
  // Sleeps to the next period of `role` (or not at all when back to back);
  // records the iteration's statistics.
  void pace(Role role, double period, double start, double& previous_start, double& deadline);
  bool wait_while_stalled(Role role);
  // Pins the calling thread and raises its priority as the settings ask.
  void configure(Role role);
  // Waits for `deadline` (s since epoch_): by an absolute sleep, or a sleep
  // and a spin for the haptic thread in Spin mode. Returns at once when the
  // threads are being stopped.
  void wait_until(Role role, double deadline) const;
  // Sleeps until `deadline`, or until request_stop() wakes the sleepers.
  void sleep_until(double deadline) const;
  // Sets stop_ and wakes every thread sleeping on it.
  void request_stop();
  double now() const;

  World& world_;
  ThreadSettings settings_;
  // The scene versions the local and global threads work with, each its own.
  std::shared_ptr<const SceneView> local_view_, global_view_;
  // The sets published (the newest last) and every tool made, until
  // reclaim() frees them; the game thread's.
  std::vector<std::unique_ptr<ToolSet>> sets_;
  struct Retired {
    std::unique_ptr<Tool> tool;
    std::uint64_t after = 0;  // freed once every thread has seen this set version
  };
  std::vector<std::unique_ptr<Tool>> tools_;
  std::vector<Retired> retired_;
  std::atomic<const ToolSet*> set_{nullptr};
  std::atomic<std::uint64_t> seen_[3] = {};
  // 1 once the threads are to stop; also the word they sleep on (a futex on
  // Linux), so stopping does not wait for the end of a period (a second at
  // 1 Hz).
  std::atomic<int> stop_{0};
  std::atomic<bool> stalled_[3] = {};
  std::atomic<int> pinned_[3] = {};
  std::atomic<int> priority_[3] = {}, priority_error_[3] = {};
  std::atomic<bool> memory_locked_{false};
  std::atomic<HapticTiming> timing_{HapticTiming::Sleep};
  std::atomic<int> memory_lock_error_{0};
  std::atomic<int> sleep_timer_{0};
  LoopStats loop_stats_[3];
  std::atomic<std::uint64_t> invalid_poses_{0}, stale_ticks_{0}, untrusted_ticks_{0}, limited_ticks_{0},
      torn_snapshots_{0}, dropped_contacts_{0};
  mutable std::mutex results_mutex_;  // contacts and step stats for the game thread
  StepStats step_stats_;
  std::thread threads_[3];
  bool started_ = false;
  std::chrono::steady_clock::time_point epoch_;
};

}  // namespace prox::runtime
