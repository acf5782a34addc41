// The C API's shared state: the thread's last error and the world registry.
#include "capi/common.h"

namespace prox::capi {

thread_local std::string g_last_error;
std::mutex g_worlds_mutex;
std::vector<WorldEntry> g_worlds;

runtime::World& world_of(proxWorldId id, const char* what) {
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, std::string(what) + " is a null id");
  std::lock_guard<std::mutex> lock(g_worlds_mutex);
  const uint32_t i = id.index1 - 1;
  if (i >= g_worlds.size() || g_worlds[i].generation != id.generation || !g_worlds[i].world)
    fail(PROX_ERROR_INVALID_HANDLE,
         std::string(what) + " does not name a live world (destroyed, or never created)");
  if (g_worlds[i].owner != std::this_thread::get_id())
    fail(PROX_ERROR_WRONG_THREAD,
         "called from a thread other than the world's game thread (the one that created it)");
  return *g_worlds[i].world;
}

void need_api_version(int32_t apiVersion, const char* maker) {
  const int32_t major = apiVersion >> 16, minor = apiVersion & 0xFFFF;
  if (major == PROX_VERSION_MAJOR && minor >= kOldestCompatibleMinor && minor <= PROX_VERSION_MINOR) return;
  const auto version = [](int32_t a, int32_t b) { return std::to_string(a) + "." + std::to_string(b); };
  fail(PROX_ERROR_VERSION_MISMATCH,
       "def->apiVersion says API version " + version(major, minor) + " (as " + maker +
           "() of that version sets it); this library is " + version(PROX_VERSION_MAJOR, PROX_VERSION_MINOR) +
           " and takes defs of " + version(PROX_VERSION_MAJOR, kOldestCompatibleMinor) + " to " +
           version(PROX_VERSION_MAJOR, PROX_VERSION_MINOR) + " (rebuild the program against this library's headers)");
}

}  // namespace prox::capi

using namespace prox::capi;

extern "C" {

const char* proxResultString(proxResult result) {
  switch (result) {
    case PROX_SUCCESS:
      return "PROX_SUCCESS";
    case PROX_ERROR_INVALID_ARGUMENT:
      return "PROX_ERROR_INVALID_ARGUMENT";
    case PROX_ERROR_INVALID_HANDLE:
      return "PROX_ERROR_INVALID_HANDLE";
    case PROX_ERROR_INVALID_MESH:
      return "PROX_ERROR_INVALID_MESH";
    case PROX_ERROR_FILE:
      return "PROX_ERROR_FILE";
    case PROX_ERROR_PARSE:
      return "PROX_ERROR_PARSE";
    case PROX_ERROR_UNSUPPORTED:
      return "PROX_ERROR_UNSUPPORTED";
    case PROX_ERROR_VERSION_MISMATCH:
      return "PROX_ERROR_VERSION_MISMATCH";
    case PROX_ERROR_WRONG_THREAD:
      return "PROX_ERROR_WRONG_THREAD";
    case PROX_ERROR_CAPACITY:
      return "PROX_ERROR_CAPACITY";
    case PROX_ERROR_INTERNAL:
      return "PROX_ERROR_INTERNAL";
    case PROX_ERROR_BUSY:
      return "PROX_ERROR_BUSY";
    case PROX_RESULT_FORCE32:
      break;
  }
  return "unknown proxResult";
}

const char* proxGetLastError(void) { return g_last_error.c_str(); }

proxVersion proxGetVersion(void) { return {PROX_VERSION_MAJOR, PROX_VERSION_MINOR, PROX_VERSION_PATCH}; }

}  // extern "C"
