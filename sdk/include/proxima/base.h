/* Proxima's C API, its base: the export macro, the API version, results
 * and errors. Plain C11 on its own; every other part of the API includes
 * it. The conventions (units, threads, ids) are proxima/proxima.h's. */
#ifndef PROXIMA_BASE_H
#define PROXIMA_BASE_H

#include <stddef.h>
#include <stdint.h>

#include "proxima/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Overridable, so that tools that parse the header (the Python binding's
 * cffi build) can define it away. On Windows proxima.dll exports the API
 * (PROX_BUILDING_SHARED, set by its build) and every other program imports
 * it from there. */
#ifndef PROX_API
#if defined(_WIN32) && defined(PROX_BUILDING_SHARED)
#define PROX_API __declspec(dllexport)
#elif defined(_WIN32)
#define PROX_API __declspec(dllimport)
#elif defined(__GNUC__)
#define PROX_API __attribute__((visibility("default")))
#else
#define PROX_API
#endif
#endif /* PROX_API */

/* The API version this header describes. proxDefaultWorldDef() stores it in
 * the def; proxCreateWorld() takes a def of the library's major version and
 * a minor one not newer than the library's, and refuses any other. */
#define PROX_API_VERSION ((PROX_VERSION_MAJOR << 16) | PROX_VERSION_MINOR)

/* A 32-bit boolean: 0 is false, anything else true. */
typedef int32_t proxBool;

/* ---- results ----------------------------------------------------------- */

typedef enum proxResult {
  PROX_SUCCESS = 0,
  PROX_ERROR_INVALID_ARGUMENT = -1, /* NULL, NaN, out of range, malformed def */
  PROX_ERROR_INVALID_HANDLE = -2,   /* null, destroyed or foreign id */
  PROX_ERROR_INVALID_MESH = -3,     /* empty, non-finite or degenerate mesh data */
  PROX_ERROR_FILE = -4,             /* a file cannot be read */
  PROX_ERROR_PARSE = -5,            /* a file's content is malformed */
  PROX_ERROR_UNSUPPORTED = -6,      /* valid input using an unsupported feature */
  PROX_ERROR_VERSION_MISMATCH = -7, /* header and library disagree */
  PROX_ERROR_WRONG_THREAD = -8,     /* called from a thread the function does not allow */
  PROX_ERROR_CAPACITY = -9,         /* an output buffer is too small (the count says how big) */
  PROX_ERROR_INTERNAL = -10,        /* a bug in Proxima: please report it with the message */
  PROX_ERROR_BUSY = -11,            /* the world's threads are running: stop them first */
  PROX_RESULT_FORCE32 = 0x7FFFFFFF
} proxResult;

/* A short, static name for a result ("PROX_ERROR_INVALID_HANDLE"). Any thread. */
PROX_API const char* proxResultString(proxResult result);

/* The message of the last error on the calling thread, naming the offending
 * argument; "" when the last call succeeded. Valid until the next call on
 * this thread. Any thread. */
PROX_API const char* proxGetLastError(void);

/* The library's version (compare with PROX_VERSION_* of this header). Any thread. */
typedef struct proxVersion {
  int32_t major, minor, patch;
} proxVersion;
PROX_API proxVersion proxGetVersion(void);

#ifdef __cplusplus
}
#endif

#endif /* PROXIMA_BASE_H */
