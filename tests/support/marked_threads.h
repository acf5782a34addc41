// Counts what the haptic path must never do: the test marks a thread (the
// haptic thread, through its device callback; a pusher around PushPose), and
// every allocation (operator new) and, outside ThreadSanitizer, which owns
// pthread_mutex_lock itself, every mutex lock made on a marked thread is
// counted. Link the proxima_marked_threads object library into the test
// executable: its replacements of operator new and pthread_mutex_lock then
// also catch the calls libproxima.so makes.
#pragma once

#include <cstddef>

namespace prox::testing {

// Marks or unmarks the calling thread.
void mark_this_thread(bool marked);
bool this_thread_marked();
// Counts since the program started, over every marked thread.
long marked_allocations();
long marked_locks();
// The largest single allocation on a marked thread, in bytes.
std::size_t marked_largest_allocation();
// Back to zero (between tests of one program, after checking that the
// counting sees the library's own calls).
void reset_marked_counts();
// Whether mutex locks are counted in this build (not under ThreadSanitizer,
// nor on Windows, where no function of another DLL can be replaced).
constexpr bool kCountsLocks =
#if defined(__SANITIZE_THREAD__) || defined(_WIN32)
    false;
#else
    true;
#endif
// Whether the counting sees what the shared library does: not on Windows,
// where proxima.dll has its own operator new, which the program's does not
// replace.
constexpr bool kSeesLibrary =
#if defined(_WIN32)
    false;
#else
    true;
#endif

// Marks the calling thread for its scope.
class MarkedScope {
 public:
  MarkedScope() { mark_this_thread(true); }
  ~MarkedScope() { mark_this_thread(false); }
  MarkedScope(const MarkedScope&) = delete;
  MarkedScope& operator=(const MarkedScope&) = delete;
};

}  // namespace prox::testing
