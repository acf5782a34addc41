// The mock runtime's spaces and haptics (mock_runtime.cpp has the rest):
// reference and action spaces located in the runtime's world, the grip from
// the script, and every vibration logged for the test.
#include "mock_state.h"

#include <algorithm>

namespace prox::mock_xr {
XRAPI_ATTR XrResult XRAPI_CALL CreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* space) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_LOCAL &&
      info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_STAGE &&
      info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_VIEW)
    return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
  auto s = std::make_unique<Space>();
  s->reference = info->referenceSpaceType;
  s->offset = of(info->poseInReferenceSpace);
  *space = new_handle<XrSpace>();
  g.spaces[*space] = std::move(s);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* count,
                                                        XrReferenceSpaceType* spaces) {
  CHECK_SESSION(session);
  const XrReferenceSpaceType all[] = {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                                      XR_REFERENCE_SPACE_TYPE_STAGE};
  *count = 3;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < 3) return XR_ERROR_SIZE_INSUFFICIENT;
  std::copy(all, all + 3, spaces);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* info,
                                                 XrSpace* space) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  const auto a = g.actions.find(info->action);
  if (a == g.actions.end()) return XR_ERROR_HANDLE_INVALID;
  if (a->second->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
  auto s = std::make_unique<Space>();
  s->action = true;
  s->poseAction = info->action;
  s->subaction = info->subactionPath;
  s->offset = of(info->poseInActionSpace);
  *space = new_handle<XrSpace>();
  g.spaces[*space] = std::move(s);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroySpace(XrSpace space) {
  std::lock_guard<std::mutex> lock(g.mutex);
  return g.spaces.erase(space) ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
}

// A space's pose in the runtime's world, or false when it is not located.
static bool world_pose(const Space& s, XrTime t, Pose* pose, V* velocity, V* angular) {
  *velocity = *angular = {0, 0, 0};
  if (!s.action) {
    *pose = s.offset;
    return true;
  }
  if (!action_active(s.poseAction, s.subaction)) return false;
  const Pose grip = grip_at(t, velocity, angular);
  // The offset's lever arm adds omega x r to the linear velocity.
  const V r = rotate(grip.q, s.offset.p);
  const V& w = *angular;
  velocity->x += w.y * r.z - w.z * r.y;
  velocity->y += w.z * r.x - w.x * r.z;
  velocity->z += w.x * r.y - w.y * r.x;
  *pose = compose(grip, s.offset);
  return true;
}

XRAPI_ATTR XrResult XRAPI_CALL LocateSpace(XrSpace space, XrSpace base, XrTime time,
                                           XrSpaceLocation* location) {
  const Inside inside;
  std::lock_guard<std::mutex> lock(g.mutex);
  const auto s = g.spaces.find(space), b = g.spaces.find(base);
  if (s == g.spaces.end() || b == g.spaces.end()) return XR_ERROR_HANDLE_INVALID;
  if (time <= 0) return XR_ERROR_TIME_INVALID;
  if (s->second->action) g_locates.fetch_add(1);
  auto* velocity = static_cast<XrSpaceVelocity*>(location->next);
  if (velocity && velocity->type != XR_TYPE_SPACE_VELOCITY) velocity = nullptr;
  location->locationFlags = 0;
  location->pose = {{0, 0, 0, 1}, {0, 0, 0}};
  if (velocity) velocity->velocityFlags = 0;
  Pose ps, pb;
  V vs, ws, vb, wb;
  if (!world_pose(*s->second, time, &ps, &vs, &ws) || !world_pose(*b->second, time, &pb, &vb, &wb))
    return XR_SUCCESS;
  const Pose inv = inverse(pb);
  location->pose = to_xr(compose(inv, ps));
  // Untracked: the pose is left where the script has it (a runtime's pose
  // without valid bits means nothing), so a caller that ignores the bits
  // keeps the tool in contact and is caught.
  if (s->second->action && !g.tracked) return XR_SUCCESS;
  location->locationFlags = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
                            XR_SPACE_LOCATION_POSITION_TRACKED_BIT |
                            XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  if (velocity) {  // reference spaces do not move: the velocities in base's axes
    const V v = rotate(inv.q, vs), w = rotate(inv.q, ws);
    velocity->linearVelocity = {float(v.x), float(v.y), float(v.z)};
    velocity->angularVelocity = {float(w.x), float(w.y), float(w.z)};
    velocity->velocityFlags = XR_SPACE_VELOCITY_LINEAR_VALID_BIT | XR_SPACE_VELOCITY_ANGULAR_VALID_BIT;
  }
  return XR_SUCCESS;
}

static XrResult log_haptic(XrSession session, const XrHapticActionInfo* info, const XrHapticVibration* v) {
  const Inside inside;
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  const auto a = g.actions.find(info->action);
  if (a == g.actions.end()) return XR_ERROR_HANDLE_INVALID;
  if (a->second->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
  ProxMockXrVibration e{};
  e.time = now_ns();
  e.stop = v ? 0 : 1;
  if (v) e.amplitude = v->amplitude, e.duration = v->duration, e.frequency = v->frequency;
  e.result = answers() ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  if (v && !(v->amplitude >= 0.0f && v->amplitude <= 1.0f)) e.result = XR_ERROR_VALIDATION_FAILURE;
  g.log.push_back(e);
  return e.result;
}

XRAPI_ATTR XrResult XRAPI_CALL ApplyHapticFeedback(XrSession session, const XrHapticActionInfo* info,
                                                   const XrHapticBaseHeader* haptic) {
  if (haptic->type != XR_TYPE_HAPTIC_VIBRATION) return XR_ERROR_VALIDATION_FAILURE;
  return log_haptic(session, info, reinterpret_cast<const XrHapticVibration*>(haptic));
}

XRAPI_ATTR XrResult XRAPI_CALL StopHapticFeedback(XrSession session, const XrHapticActionInfo* info) {
  return log_haptic(session, info, nullptr);
}

}  // namespace prox::mock_xr
