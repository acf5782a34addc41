// The fuzz targets' own checks: a broken promise aborts, which libFuzzer
// (and the replay driver, by dying) reports like a crash.
#pragma once

#include <cstdio>
#include <cstdlib>

#define PROX_FUZZ_CHECK(condition, ...)                                                  \
  do {                                                                                   \
    if (!(condition)) {                                                                  \
      std::fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #condition); \
      std::fprintf(stderr, __VA_ARGS__);                                                 \
      std::fprintf(stderr, "\n");                                                        \
      std::abort();                                                                      \
    }                                                                                    \
  } while (0)
