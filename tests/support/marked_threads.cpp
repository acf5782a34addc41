#include "marked_threads.h"

#include <atomic>
#include <cstdlib>
#include <new>

#if !defined(__SANITIZE_THREAD__) && !defined(_WIN32)
#include <dlfcn.h>
#include <pthread.h>
#endif

namespace {
thread_local bool t_marked = false;
std::atomic<long> g_allocations{0};
std::atomic<long> g_locks{0};
std::atomic<std::size_t> g_largest{0};

void* allocate(std::size_t n) {
  if (t_marked) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    std::size_t largest = g_largest.load(std::memory_order_relaxed);
    while (n > largest && !g_largest.compare_exchange_weak(largest, n, std::memory_order_relaxed)) {
    }
  }
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

#if !defined(__SANITIZE_THREAD__) && !defined(_WIN32)
namespace {
using LockFn = int (*)(pthread_mutex_t*);
// Looked up at the first lock, not by a static initialiser: preloaded
// libraries (umockdev's GLib) lock before this file's initialisers run.
std::atomic<LockFn> g_real_lock{nullptr};
}  // namespace
extern "C" int pthread_mutex_lock(pthread_mutex_t* m) {
  if (t_marked) g_locks.fetch_add(1, std::memory_order_relaxed);
  LockFn real = g_real_lock.load(std::memory_order_acquire);
  if (!real) {
    real = reinterpret_cast<LockFn>(dlsym(RTLD_NEXT, "pthread_mutex_lock"));
    g_real_lock.store(real, std::memory_order_release);
  }
  return real(m);
}
#endif

namespace prox::testing {

void mark_this_thread(bool marked) { t_marked = marked; }
bool this_thread_marked() { return t_marked; }
long marked_allocations() { return g_allocations.load(std::memory_order_relaxed); }
long marked_locks() { return g_locks.load(std::memory_order_relaxed); }
std::size_t marked_largest_allocation() { return g_largest.load(std::memory_order_relaxed); }
void reset_marked_counts() {
  g_allocations.store(0, std::memory_order_relaxed);
  g_largest.store(0, std::memory_order_relaxed);
  g_locks.store(0, std::memory_order_relaxed);
}

}  // namespace prox::testing
