// The optional helpers: Proxima's actions in the app's action set, and the
// bindings they need per interaction profile, for the app's one suggest
// call (a second call for a profile would replace the app's own bindings).
#include "capi/common.h"

#include <proxima/proxima_openxr.h>

#include <cstring>

using namespace prox::capi;

namespace {

// The profiles of the core specification that have a grip pose, and
// whether they have a haptic output.
struct Profile {
  const char* path;
  bool haptic;
};
constexpr Profile kProfiles[] = {
    {"/interaction_profiles/khr/simple_controller", true},
    {"/interaction_profiles/google/daydream_controller", false},
    {"/interaction_profiles/htc/vive_controller", true},
    {"/interaction_profiles/microsoft/motion_controller", true},
    {"/interaction_profiles/microsoft/xbox_controller", false},
    {"/interaction_profiles/oculus/go_controller", false},
    {"/interaction_profiles/oculus/touch_controller", true},
    {"/interaction_profiles/valve/index_controller", true},
};

template <typename Pfn>
Pfn resolve(PFN_xrGetInstanceProcAddr gipa, XrInstance instance, const char* name) {
  PFN_xrVoidFunction f = nullptr;
  const XrResult r = gipa(instance, name, &f);
  if (XR_FAILED(r) || !f)
    fail(PROX_ERROR_INVALID_ARGUMENT, std::string("gipa gives no ") + name + " (XrResult " +
                                          std::to_string(int(r)) + "): is instance live?");
  return reinterpret_cast<Pfn>(f);
}

XrPath path(PFN_xrStringToPath to_path, XrInstance instance, const std::string& s) {
  XrPath p = XR_NULL_PATH;
  const XrResult r = to_path(instance, s.c_str(), &p);
  if (XR_FAILED(r))
    fail(PROX_ERROR_INVALID_ARGUMENT,
         "xrStringToPath(\"" + s + "\") failed (XrResult " + std::to_string(int(r)) + ")");
  return p;
}

// OpenXR's rule for action names: lower-case letters, digits, '-', '_', '.'.
void check_prefix(const char* prefix) {
  need(prefix, "namePrefix");
  const std::size_t n = std::strlen(prefix);
  if (n == 0 || n + 7 >= XR_MAX_ACTION_NAME_SIZE)
    fail(PROX_ERROR_INVALID_ARGUMENT,
         "namePrefix must have 1 to " + std::to_string(XR_MAX_ACTION_NAME_SIZE - 8) + " characters");
  for (std::size_t i = 0; i < n; ++i) {
    const char c = prefix[i];
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.'))
      fail(PROX_ERROR_INVALID_ARGUMENT, std::string("namePrefix \"") + prefix +
                                            "\" may hold only a-z, 0-9, '-', '_' and '.' (OpenXR's rule)");
  }
}

}  // namespace

extern "C" {

proxResult proxXrCreateActions(PFN_xrGetInstanceProcAddr gipa, XrInstance instance, XrActionSet set,
                               const char* namePrefix, XrAction* poseAction, XrAction* hapticAction) {
  return guard("proxXrCreateActions", [&] {
    need(poseAction, "poseAction");
    need(hapticAction, "hapticAction");
    *poseAction = *hapticAction = XR_NULL_HANDLE;
    if (!gipa) fail(PROX_ERROR_INVALID_ARGUMENT, "gipa is NULL");
    if (instance == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "instance is XR_NULL_HANDLE");
    if (set == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "set is XR_NULL_HANDLE");
    check_prefix(namePrefix);
    const auto to_path = resolve<PFN_xrStringToPath>(gipa, instance, "xrStringToPath");
    const auto create = resolve<PFN_xrCreateAction>(gipa, instance, "xrCreateAction");
    const auto destroy = resolve<PFN_xrDestroyAction>(gipa, instance, "xrDestroyAction");
    const XrPath hands[2] = {path(to_path, instance, "/user/hand/left"),
                             path(to_path, instance, "/user/hand/right")};
    const auto make = [&](XrActionType type, const char* suffix, const char* what) {
      XrActionCreateInfo info{};
      info.type = XR_TYPE_ACTION_CREATE_INFO;
      info.actionType = type;
      std::snprintf(info.actionName, sizeof info.actionName, "%s_%s", namePrefix, suffix);
      std::snprintf(info.localizedActionName, sizeof info.localizedActionName, "Proxima %s %s", namePrefix,
                    what);
      info.countSubactionPaths = 2;
      info.subactionPaths = hands;
      XrAction a = XR_NULL_HANDLE;
      const XrResult r = create(set, &info, &a);
      if (XR_FAILED(r))
        fail(PROX_ERROR_INVALID_ARGUMENT,
             std::string("xrCreateAction(\"") + info.actionName + "\") failed (XrResult " +
                 std::to_string(int(r)) + "): is set live and not yet attached, and the name free in it?");
      return a;
    };
    const XrAction pose = make(XR_ACTION_TYPE_POSE_INPUT, "grip", "tool grip");
    XrAction haptic = XR_NULL_HANDLE;
    try {
      haptic = make(XR_ACTION_TYPE_VIBRATION_OUTPUT, "haptic", "contact vibration");
    } catch (const Failure&) {
      destroy(pose);
      throw;
    }
    *poseAction = pose;
    *hapticAction = haptic;
  });
}

proxResult proxXrGetSuggestedBindings(PFN_xrGetInstanceProcAddr gipa, XrInstance instance,
                                      const char* interactionProfile, const char* hand, XrAction poseAction,
                                      XrAction hapticAction, XrActionSuggestedBinding* bindings,
                                      int32_t capacity, int32_t* count) {
  return guard("proxXrGetSuggestedBindings", [&] {
    need(count, "count");
    *count = 0;
    if (!gipa) fail(PROX_ERROR_INVALID_ARGUMENT, "gipa is NULL");
    if (instance == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "instance is XR_NULL_HANDLE");
    need(interactionProfile, "interactionProfile");
    need(hand, "hand");
    if (poseAction == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "poseAction is XR_NULL_HANDLE");
    if (capacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "capacity must be >= 0");
    if (capacity > 0) need(bindings, "bindings");
    std::string side = hand;
    if (side.rfind("/user/hand/", 0) == 0) side = side.substr(11);  // the path works too
    if (side != "left" && side != "right")
      fail(PROX_ERROR_INVALID_ARGUMENT,
           std::string("hand must be \"left\" or \"right\" (or /user/hand/...; it is \"") + hand + "\")");
    const Profile* profile = nullptr;
    for (const Profile& p : kProfiles)
      if (std::strcmp(p.path, interactionProfile) == 0) profile = &p;
    if (!profile) {
      std::string known;
      for (const Profile& p : kProfiles) known += std::string(known.empty() ? "" : ", ") + p.path;
      fail(PROX_ERROR_UNSUPPORTED, std::string("interactionProfile \"") + interactionProfile +
                                       "\" is not one Proxima knows (" + known + ")");
    }
    const bool haptic = hapticAction != XR_NULL_HANDLE && profile->haptic;
    const int32_t n = haptic ? 2 : 1;
    *count = n;
    if (capacity < n)
      fail(PROX_ERROR_CAPACITY, "bindings holds " + std::to_string(capacity) + " but " + std::to_string(n) +
                                    " are needed (*count)");
    const auto to_path = resolve<PFN_xrStringToPath>(gipa, instance, "xrStringToPath");
    const std::string user = "/user/hand/" + side;
    bindings[0] = {poseAction, path(to_path, instance, user + "/input/grip/pose")};
    if (haptic) bindings[1] = {hapticAction, path(to_path, instance, user + "/output/haptic")};
  });
}

}  // extern "C"
