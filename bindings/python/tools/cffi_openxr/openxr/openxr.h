/* What cffi needs of <openxr/openxr.h> to parse proxima_openxr.h: the few
 * types its declarations use, with OpenXR 1.0's values. CMakeLists.txt puts
 * this directory first on the preprocessor's path when it makes the cffi
 * declarations, so the package describes the OpenXR functions whether or not
 * the machine that builds it has the OpenXR headers (a library built without
 * PROX_WITH_OPENXR then lacks the functions, and the package says so), and
 * cffi does not parse all of openxr.h (GCC attributes it cannot read).
 *
 * The handles are uint64_t: what they are on 32-bit platforms, and on 64-bit
 * ones the size, alignment and calling convention of the pointers they are
 * there; the binding takes and returns them as Python ints. The test
 * bindings/python/tests/test_openxr.py drives the real loader through them. */
#ifndef PROXIMA_CFFI_OPENXR_H
#define PROXIMA_CFFI_OPENXR_H

typedef int32_t XrResult;
typedef uint64_t XrInstance;
typedef uint64_t XrSession;
typedef uint64_t XrSpace;
typedef uint64_t XrAction;
typedef uint64_t XrActionSet;
typedef uint64_t XrPath;
typedef int64_t XrTime;
typedef int64_t XrDuration;

typedef enum XrSessionState {
  XR_SESSION_STATE_UNKNOWN = 0,
  XR_SESSION_STATE_IDLE = 1,
  XR_SESSION_STATE_READY = 2,
  XR_SESSION_STATE_SYNCHRONIZED = 3,
  XR_SESSION_STATE_VISIBLE = 4,
  XR_SESSION_STATE_FOCUSED = 5,
  XR_SESSION_STATE_STOPPING = 6,
  XR_SESSION_STATE_LOSS_PENDING = 7,
  XR_SESSION_STATE_EXITING = 8
} XrSessionState;

typedef struct XrActionSuggestedBinding {
  XrAction action;
  XrPath binding;
} XrActionSuggestedBinding;

typedef void (*PFN_xrVoidFunction)(void);
typedef XrResult (*PFN_xrGetInstanceProcAddr)(XrInstance instance, const char* name, PFN_xrVoidFunction* function);

#endif
