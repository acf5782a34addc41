/* Proxima version. The C API (next to this header) reports the same numbers at
 * run time, so a caller can check that header and library agree. */
#ifndef PROXIMA_VERSION_H
#define PROXIMA_VERSION_H

#define PROX_VERSION_MAJOR 0
#define PROX_VERSION_MINOR 4
#define PROX_VERSION_PATCH 0
#define PROX_VERSION_STRING "0.4.0"

#endif
