/* OpenXR, the integration walkthrough: an app that owns its OpenXR session
 * hands Proxima its right controller. The controller's grip holds the tool
 * (a bunny), and the force of its contacts with another bunny comes back as
 * the controller's vibration.
 *
 * Headless (XR_MND_headless: no graphics binding, no swapchain), with the
 * frame loop that extension describes: the frame calls only while
 * xrWaitFrame gives a display time, else paced by sleep; "now" from
 * whatever clock the runtime offers. It runs in CI on the test runtime of
 * tests/openxr (whose scripted hand reaches forward 0.15 m every 4 s, with
 * or without real runtimes' habits) and by hand on Monado; the runtimes
 * and what each does are in docs/openxr.md, with the rules the app follows
 * (Proxima borrows, never owns).
 *
 *   openxr_sample [path/to/mesh.obj|.gltf|.glb] [seconds]
 */
#if defined(_WIN32)
#define XR_USE_PLATFORM_WIN32
#include <windows.h>
#else
#define XR_USE_TIMESPEC
#include <time.h>
#endif

#include <proxima/proxima_openxr.h>

#include <openxr/openxr_platform.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int xr_ok(XrResult r, const char* what) {
  if (XR_SUCCEEDED(r)) return 1;
  fprintf(stderr, "%s failed: XrResult %d\n", what, (int)r);
  return 0;
}

static int ok(proxResult r, const char* what) {
  if (r == PROX_SUCCESS) return 1;
  fprintf(stderr, "%s failed: %s: %s\n", what, proxResultString(r), proxGetLastError());
  return 0;
}

static int has_extension(const char* name) {
  uint32_t n = 0;
  if (!xr_ok(xrEnumerateInstanceExtensionProperties(NULL, 0, &n, NULL),
             "xrEnumerateInstanceExtensionProperties"))
    return 0;
  XrExtensionProperties* all = calloc(n, sizeof *all);
  for (uint32_t i = 0; i < n; ++i) all[i].type = XR_TYPE_EXTENSION_PROPERTIES;
  int found = 0;
  if (xr_ok(xrEnumerateInstanceExtensionProperties(NULL, n, &n, all),
            "xrEnumerateInstanceExtensionProperties"))
    for (uint32_t i = 0; i < n; ++i) found |= strcmp(all[i].extensionName, name) == 0;
  free(all);
  return found;
}

/* The app's state, as any OpenXR app has it. */
typedef struct App {
  XrInstance instance;
  XrSession session;
  XrSpace local;
  XrActionSet set;
  XrAction menu;         /* the app's own action */
  XrAction grip, haptic; /* Proxima's, in the app's set */
  XrPath right;
  XrSessionState state;
  int running;
  double state_since;    /* when the state last changed (now_s) */
  int frame_calls;       /* 0 once xrWaitFrame gave no display time (headless) */
  XrTime display_time;   /* the last predicted display time > 0, ... */
  double display_at;     /* ... and when it came */
  XrTime event_time;     /* the newest event time > 0, ... */
  double event_at;       /* ... and when it was polled */
  int time_extension;    /* 1: timespec (2: Windows' performance counter) conversion enabled */
  proxXrDeviceId device; /* 0 until Proxima holds the controller */
} App;

static double now_s(void) {
#if defined(_WIN32)
  LARGE_INTEGER c, f;
  QueryPerformanceCounter(&c);
  QueryPerformanceFrequency(&f);
  return (double)c.QuadPart / (double)f.QuadPart;
#else
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
#endif
}

static void sleep_s(double s) {
#if defined(_WIN32)
  Sleep((DWORD)(s * 1000.0));
#else
  struct timespec t = {0, (long)(s * 1e9)};
  nanosleep(&t, NULL);
#endif
}

static const char* state_name(XrSessionState s) {
  static const char* names[] = {"XR_SESSION_STATE_UNKNOWN",      "XR_SESSION_STATE_IDLE",
                                "XR_SESSION_STATE_READY",        "XR_SESSION_STATE_SYNCHRONIZED",
                                "XR_SESSION_STATE_VISIBLE",      "XR_SESSION_STATE_FOCUSED",
                                "XR_SESSION_STATE_STOPPING",     "XR_SESSION_STATE_LOSS_PENDING",
                                "XR_SESSION_STATE_EXITING"};
  return s >= 0 && s <= XR_SESSION_STATE_EXITING ? names[s] : "an unknown XrSessionState";
}

/* "Now" as an XrTime, from the first clock the runtime offers: its time
 * conversion extension, else the last display time it predicted, else the
 * newest time an event carried, each advanced by the app's monotonic clock.
 * 0 when it has offered none yet. */
static XrTime xr_now(const App* app) {
  XrTime t = 0;
#if defined(_WIN32)
  PFN_xrConvertWin32PerformanceCounterToTimeKHR convert = NULL;
  if (app->time_extension == 2 &&
      XR_SUCCEEDED(xrGetInstanceProcAddr(app->instance, "xrConvertWin32PerformanceCounterToTimeKHR",
                                         (PFN_xrVoidFunction*)&convert))) {
    LARGE_INTEGER counter;
    QueryPerformanceCounter(&counter);
    if (XR_SUCCEEDED(convert(app->instance, &counter, &t)) && t > 0) return t;
  }
#else
  PFN_xrConvertTimespecTimeToTimeKHR convert = NULL;
  if (app->time_extension == 1 && XR_SUCCEEDED(xrGetInstanceProcAddr(app->instance, "xrConvertTimespecTimeToTimeKHR",
                                                                     (PFN_xrVoidFunction*)&convert))) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    if (XR_SUCCEEDED(convert(app->instance, &ts, &t)) && t > 0) return t;
  }
#endif
  if (app->display_time > 0) return app->display_time + (XrTime)((now_s() - app->display_at) * 1e9);
  if (app->event_time > 0) return app->event_time + (XrTime)((now_s() - app->event_at) * 1e9);
  return 0;
}

/* Polls every event and forwards session state changes to Proxima: only the
 * app polls (xrPollEvent consumes events). */
static int poll_events(App* app) {
  XrEventDataBuffer event = {.type = XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(app->instance, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      const XrEventDataSessionStateChanged* changed = (const XrEventDataSessionStateChanged*)&event;
      app->state = changed->state;
      app->state_since = now_s();
      if (app->device.index1 && !ok(proxXrDevice_OnSessionState(app->device, app->state), "OnSessionState"))
        return 0;
      if (changed->time > app->event_time) { /* a time the runtime gave: Proxima's last resort too */
        app->event_time = changed->time;
        app->event_at = now_s();
        if (app->device.index1 && !ok(proxXrDevice_OnRuntimeTime(app->device, changed->time), "OnRuntimeTime"))
          return 0;
      }
      if (app->state == XR_SESSION_STATE_READY) {
        XrSessionBeginInfo begin = {.type = XR_TYPE_SESSION_BEGIN_INFO};
        begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        if (!xr_ok(xrBeginSession(app->session, &begin), "xrBeginSession")) return 0;
        app->running = 1;
      } else if (app->state == XR_SESSION_STATE_STOPPING) {
        if (!xr_ok(xrEndSession(app->session), "xrEndSession")) return 0;
        app->running = 0;
      }
    }
    event.type = XR_TYPE_EVENT_DATA_BUFFER;
  }
  return 1;
}

/* One frame: wait, begin, sync the app's set (which holds Proxima's
 * actions: Proxima never syncs), tell Proxima the frame's time, end. Headless
 * as XR_MND_headless allows: once xrWaitFrame gives no display time (Monado
 * gives 0 and does not block), no frame calls; a sync and a sleep instead. */
static int frame(App* app) {
  if (!poll_events(app)) return 0;
  if (!app->running) {
    sleep_s(0.01);
    return 1;
  }
  XrFrameState fs = {.type = XR_TYPE_FRAME_STATE};
  if (app->frame_calls) {
    if (!xr_ok(xrWaitFrame(app->session, NULL, &fs), "xrWaitFrame")) return 0;
    if (fs.predictedDisplayTime > 0) {
      if (!xr_ok(xrBeginFrame(app->session, NULL), "xrBeginFrame")) return 0;
      app->display_time = fs.predictedDisplayTime;
      app->display_at = now_s();
    } else {
      app->frame_calls = 0;
      printf("xrWaitFrame gives no display time (headless): no frame calls from here on, paced by sleep\n");
    }
  }
  XrActiveActionSet active = {app->set, XR_NULL_PATH};
  XrActionsSyncInfo sync = {.type = XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  if (!xr_ok(xrSyncActions(app->session, &sync), "xrSyncActions")) return 0;
  if (!app->frame_calls) {
    sleep_s(1.0 / 90.0);
    return 1;
  }
  if (app->device.index1 &&
      !ok(proxXrDevice_OnFrame(app->device, fs.predictedDisplayTime, fs.predictedDisplayPeriod), "OnFrame"))
    return 0;
  XrFrameEndInfo end = {.type = XR_TYPE_FRAME_END_INFO};
  end.displayTime = fs.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  if (!xr_ok(xrEndFrame(app->session, &end), "xrEndFrame")) return 0;
  if (fs.predictedDisplayPeriod <= 0) sleep_s(1.0 / 90.0); /* a wait that does not pace */
  return 1;
}

static const char* time_source_name(proxXrTimeSource s) {
  switch (s) {
    case PROX_XR_TIME_TIMESPEC: return "XR_KHR_convert_timespec_time";
    case PROX_XR_TIME_WIN32_PERFORMANCE_COUNTER: return "XR_KHR_win32_convert_performance_counter_time";
    case PROX_XR_TIME_FRAMES: return "the predicted display times";
    case PROX_XR_TIME_OWN_CLOCK: return "Proxima's own clock from the runtime's times";
    default: return "nowhere (no time)";
  }
}

int main(int argc, char** argv) {
  const char* mesh_path = argc > 1 ? argv[1] : PROX_OPENXR_DEFAULT_MESH;
  const double seconds = argc > 2 ? atof(argv[2]) : 5.0;
  App app;
  memset(&app, 0, sizeof app);
  app.frame_calls = 1;

  /* 1. The instance: headless, and the time conversion extension when the
   *    runtime has one (Proxima's thread then asks OpenXR for "now";
   *    without, it counts from the times the runtime gives). */
#if defined(_WIN32)
  const char* time_extension = XR_KHR_WIN32_CONVERT_PERFORMANCE_COUNTER_TIME_EXTENSION_NAME;
  const int time_kind = 2;
#else
  const char* time_extension = XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME;
  const int time_kind = 1;
#endif
  app.time_extension = has_extension(time_extension) ? time_kind : 0;
  if (!has_extension(XR_MND_HEADLESS_EXTENSION_NAME)) {
    fprintf(stderr, "the OpenXR runtime does not offer XR_MND_headless: this sample needs a headless session\n");
    return 1;
  }
  const char* extensions[2] = {XR_MND_HEADLESS_EXTENSION_NAME, time_extension};
  XrInstanceCreateInfo ici = {.type = XR_TYPE_INSTANCE_CREATE_INFO};
  strcpy(ici.applicationInfo.applicationName, "proxima-openxr-sample");
  ici.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  ici.enabledExtensionCount = app.time_extension ? 2 : 1;
  ici.enabledExtensionNames = extensions;
  if (!xr_ok(xrCreateInstance(&ici, &app.instance),
             "xrCreateInstance (is an OpenXR runtime with XR_MND_headless active?)"))
    return 1;
  XrSystemGetInfo sgi = {.type = XR_TYPE_SYSTEM_GET_INFO};
  sgi.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system;
  if (!xr_ok(xrGetSystem(app.instance, &sgi, &system), "xrGetSystem")) return 1;

  /* 2. The app's one action set, with Proxima's two actions created in it,
   *    and one suggest call per profile holding the app's bindings and
   *    Proxima's (a second call for a profile would replace the first). */
  XrActionSetCreateInfo asci = {.type = XR_TYPE_ACTION_SET_CREATE_INFO};
  strcpy(asci.actionSetName, "gameplay");
  strcpy(asci.localizedActionSetName, "Gameplay");
  if (!xr_ok(xrCreateActionSet(app.instance, &asci, &app.set), "xrCreateActionSet")) return 1;
  XrActionCreateInfo aci = {.type = XR_TYPE_ACTION_CREATE_INFO};
  aci.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
  strcpy(aci.actionName, "menu");
  strcpy(aci.localizedActionName, "Menu");
  if (!xr_ok(xrCreateAction(app.set, &aci, &app.menu), "xrCreateAction")) return 1;
  if (!ok(proxXrCreateActions(xrGetInstanceProcAddr, app.instance, app.set, "proxima", &app.grip,
                              &app.haptic),
          "proxXrCreateActions"))
    return 1;
  const char* profile = "/interaction_profiles/khr/simple_controller";
  XrActionSuggestedBinding bindings[8];
  int32_t count = 0;
  bindings[0].action = app.menu;
  xrStringToPath(app.instance, "/user/hand/left/input/menu/click", &bindings[0].binding);
  if (!ok(proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance, profile, "right", app.grip,
                                     app.haptic, bindings + 1, 7, &count),
          "proxXrGetSuggestedBindings"))
    return 1;
  XrInteractionProfileSuggestedBinding suggested = {.type = XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  xrStringToPath(app.instance, profile, &suggested.interactionProfile);
  suggested.countSuggestedBindings = (uint32_t)(1 + count);
  suggested.suggestedBindings = bindings;
  if (!xr_ok(xrSuggestInteractionProfileBindings(app.instance, &suggested),
             "xrSuggestInteractionProfileBindings"))
    return 1;
  xrStringToPath(app.instance, "/user/hand/right", &app.right);

  /* 3. The session (headless: no graphics binding), the world space, and
   *    the set attached: once per session, so Proxima's actions must be in
   *    it by now. */
  XrSessionCreateInfo sci = {.type = XR_TYPE_SESSION_CREATE_INFO};
  sci.systemId = system;
  if (!xr_ok(xrCreateSession(app.instance, &sci, &app.session), "xrCreateSession")) return 1;
  XrReferenceSpaceCreateInfo rsci = {.type = XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  rsci.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  rsci.poseInReferenceSpace.orientation.w = 1.0f;
  if (!xr_ok(xrCreateReferenceSpace(app.session, &rsci, &app.local), "xrCreateReferenceSpace")) return 1;
  XrSessionActionSetsAttachInfo attach = {.type = XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &app.set;
  if (!xr_ok(xrAttachSessionActionSets(app.session, &attach), "xrAttachSessionActionSets")) return 1;

  /* 4. Run frames until the session is focused and the hand located (the
   *    app's own look at the grip, to put the scene in front of it). */
  XrSpace grip_space;
  XrActionSpaceCreateInfo spci = {.type = XR_TYPE_ACTION_SPACE_CREATE_INFO};
  spci.action = app.grip;
  spci.subactionPath = app.right;
  spci.poseInActionSpace.orientation.w = 1.0f;
  if (!xr_ok(xrCreateActionSpace(app.session, &spci, &grip_space), "xrCreateActionSpace")) return 1;
  XrSpaceLocation hand = {.type = XR_TYPE_SPACE_LOCATION};
  const double wait_until = now_s() + 10.0;
  while (!(hand.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT)) {
    if (!frame(&app)) return 1;
    const double now = now_s();
    if (app.running && app.state != XR_SESSION_STATE_FOCUSED && now - app.state_since > 5.0) {
      fprintf(stderr,
              "the session stayed in %s for 5 s after xrBeginSession: the runtime never focused it, so it gives "
              "this app no input (stock Monado's headless sessions stay in XR_SESSION_STATE_READY; see "
              "docs/openxr.md)\n",
              state_name(app.state));
      return 1;
    }
    if (now > wait_until) {
      if (app.state != XR_SESSION_STATE_FOCUSED)
        fprintf(stderr, "the session never became focused within 10 s (it is in %s)\n", state_name(app.state));
      else if (xr_now(&app) == 0)
        fprintf(stderr,
                "the runtime offers no time: no %s, no display time from xrWaitFrame and no event time\n",
                time_extension);
      else
        fprintf(stderr, "the right hand was not tracked within 10 s (is a right controller on?)\n");
      return 1;
    }
    const XrTime t = app.state == XR_SESSION_STATE_FOCUSED ? xr_now(&app) : 0;
    hand.locationFlags = 0;
    if (t > 0 && !xr_ok(xrLocateSpace(grip_space, app.local, t, &hand), "xrLocateSpace")) return 1;
  }
  xrDestroySpace(grip_space);
  printf("right hand at (%.3f, %.3f, %.3f) in LOCAL\n", hand.pose.position.x, hand.pose.position.y,
         hand.pose.position.z);

  /* 5. Proxima's scene, in its own world frame: OpenXR's LOCAL space
   *    rotated so that reaching forward (-z) moves the tool along -x, and a
   *    rock bunny just within reach. */
  proxWorldDef wd = proxDefaultWorldDef();
  proxWorldId world;
  if (!ok(proxCreateWorld(&wd, &world), "proxCreateWorld")) return 1;
  proxMeshId bunny;
  if (!ok(proxWorld_LoadMesh(world, mesh_path, &bunny), "proxWorld_LoadMesh")) return 1;
  proxMeshInfo info;
  if (!ok(proxMesh_GetInfo(bunny, &info), "proxMesh_GetInfo")) return 1;
  const double width = info.boundsMax.x - info.boundsMin.x, reach = 0.15;
  const double s = sqrt(0.5);
  const proxQuat about_y = {s, 0, s, 0}; /* +90 degrees about y: -z becomes -x */
  const proxQuat back = {s, 0, -s, 0};   /* the tool held upright in the world */
  const proxPose base_to_world = {{0, 0, 0}, about_y};
  /* Where the hand starts, in Proxima's world: R_y(90) (x, y, z) = (z, y, -x). */
  const proxVec3 start = {hand.pose.position.z, hand.pose.position.y, -hand.pose.position.x};
  proxBodyDef bd = proxDefaultBodyDef();
  bd.mesh = bunny;
  bd.pose.position = (proxVec3){start.x - reach - 0.9 * width, start.y, start.z};
  proxBodyId rock, tool;
  if (!ok(proxWorld_CreateBody(world, &bd, &rock), "proxWorld_CreateBody")) return 1;
  bd.type = PROX_BODY_TOOL;
  bd.pose.position = start;
  if (!ok(proxWorld_CreateBody(world, &bd, &tool), "proxWorld_CreateBody")) return 1;

  /* 6. The XR device: the app's handles and its xrGetInstanceProcAddr
   *    (every OpenXR call Proxima makes goes through it), attached to the
   *    tool like any device. */
  proxXrDeviceDef xd = proxDefaultXrDeviceDef();
  xd.getInstanceProcAddr = xrGetInstanceProcAddr;
  xd.instance = app.instance;
  xd.session = app.session;
  xd.baseSpace = app.local;
  xd.poseAction = app.grip;
  xd.hapticAction = app.haptic;
  xd.subactionPath = app.right;
  xd.toolInGrip.rotation = back;
  xd.baseToWorld = base_to_world;
#if defined(_WIN32)
  xd.win32PerformanceCounterTime = app.time_extension == 2;
#else
  xd.timespecTime = app.time_extension == 1;
#endif
  xd.runtimeTime = xr_now(&app); /* "now" for a runtime with no other clock */
  xd.sessionState = app.state;
  xd.forceForFullAmplitude = 2.0;
  if (!ok(proxWorld_CreateXrDevice(world, &xd, &app.device), "proxWorld_CreateXrDevice")) return 1;
  proxDeviceDef dd;
  if (!ok(proxXrDevice_GetDeviceDef(app.device, &dd), "proxXrDevice_GetDeviceDef")) return 1;
  if (!ok(proxBody_SetDevice(tool, &dd), "proxBody_SetDevice")) return 1;
  proxThreadsDef td = proxDefaultThreadsDef();
  if (!ok(proxWorld_StartThreads(world, &td), "proxWorld_StartThreads")) return 1;

  /* 7. The app's frame loop, unchanged but for OnFrame and the forwarded
   *    states; Proxima's thread locates the hand and vibrates meanwhile. */
  double felt = 0.0, next_print = 0.0;
  const double start_time = now_s();
  printf("  time   tool x (m)  |force| (N)  vibrations\n");
  while (now_s() - start_time < seconds) {
    if (!frame(&app)) return 1;
    proxWrench w;
    proxPose p;
    proxXrDeviceStats st;
    if (!ok(proxBody_GetWrench(tool, &w), "proxBody_GetWrench") ||
        !ok(proxBody_GetPose(tool, &p), "GetPose") ||
        !ok(proxXrDevice_GetStats(app.device, &st), "proxXrDevice_GetStats"))
      return 1;
    const double f = sqrt(w.force.x * w.force.x + w.force.y * w.force.y + w.force.z * w.force.z);
    if (!isfinite(f)) return 1;
    if (f > felt) felt = f;
    if (now_s() - start_time >= next_print) {
      printf("  %.2f s  %.4f  %.4f  %llu\n", now_s() - start_time, p.position.x, f,
             (unsigned long long)st.vibrationsSent);
      next_print += 0.5;
    }
  }

  /* 8. Leave: end the session through its states (forwarded as ever), then
   *    Proxima lets go (its thread stops) before the app destroys anything
   *    it borrowed. */
  if (!xr_ok(xrRequestExitSession(app.session), "xrRequestExitSession")) return 1;
  const double exit_until = now_s() + 5.0;
  while (app.state != XR_SESSION_STATE_EXITING && now_s() < exit_until)
    if (!frame(&app)) return 1;
  proxXrDeviceStats st;
  if (!ok(proxXrDevice_GetStats(app.device, &st), "proxXrDevice_GetStats")) return 1;
  if (!ok(proxXrDevice_Destroy(app.device), "proxXrDevice_Destroy")) return 1;
  proxWorld_Destroy(world);
  xrDestroySpace(app.local);
  xrDestroySession(app.session);
  xrDestroyActionSet(app.set);
  xrDestroyInstance(app.instance);
  printf(
      "xr device: %llu ticks, %llu locates, %llu untracked, %llu not focused; %llu vibrations sent, %llu "
      "refused, "
      "%llu stops; time from %s; most force felt %.3f N\n",
      (unsigned long long)st.ticks, (unsigned long long)st.locates, (unsigned long long)st.untrackedTicks,
      (unsigned long long)st.notFocusedTicks, (unsigned long long)st.vibrationsSent,
      (unsigned long long)st.vibrationsRefused, (unsigned long long)st.stopsSent,
      time_source_name(st.timeSource), felt);
  /* Fails (for its test) unless the reach was felt and vibrated. */
  return felt > 0.0 && st.vibrationsSent > 0 && st.stopsSent > 0 ? 0 : 1;
}
