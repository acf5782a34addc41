// Bodies: create, destroy, poses, and a tool's results (contacts, wrench, intersections).
#include "capi/common.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <string>

using namespace prox;
using namespace prox::capi;

namespace {

// proxBody_GetContacts and proxBody_GetContactPatches: one snapshot of the
// tool's contacts into either or both arrays. `need_contacts`: the contacts
// array is the one output (GetContacts), so a capacity needs it.
void copy_contacts(proxBodyId tool, proxContact* contacts, proxContactPatch* patches, int32_t capacity,
                   int32_t* count, bool need_contacts) {
  need(count, "count");
  *count = 0;
  if (capacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "capacity is negative");
  if (capacity > 0 && need_contacts) need(contacts, "contacts");
  if (capacity > 0 && !contacts && !patches)
    fail(PROX_ERROR_INVALID_ARGUMENT, "contacts and patches are both NULL with a capacity of " +
                                          std::to_string(capacity) + " (pass 0 to ask the count)");
  runtime::World* w = nullptr;
  const runtime::Handle h = tool_of(tool, w);
  std::vector<runtime::Contact> list;
  w->contacts(h, list);
  *count = static_cast<int32_t>(list.size());
  const std::size_t n = std::min<std::size_t>(list.size(), static_cast<std::size_t>(capacity));
  for (std::size_t i = 0; i < n; ++i) {
    const runtime::Contact& c = list[i];
    const LmdPair& p = c.lmd;
    if (contacts) {
      proxContact& out = contacts[i];
      out.other = {c.other + 1, w->body_generation(c.other), tool.world};
      out.pointTool = to_c(p.point_b);
      out.pointOther = to_c(p.point_a);
      const Vec3 d = p.point_b - p.point_a;
      const double len = glm::length(d);
      out.normal = to_c(len > 0.0 ? d / len : Vec3(0.0));
      out.distance = p.distance;
      out.triangleTool = p.tri_b;
      out.triangleOther = p.tri_a;
      out.featureTool = static_cast<int32_t>(p.feature_b.kind);
      out.featureOther = static_cast<int32_t>(p.feature_a.kind);
    }
    if (patches) {
      proxContactPatch& out = patches[i];
      out = proxContactPatch{};
      out.count = static_cast<int32_t>(std::min<std::uint32_t>(p.patch_count, INT32_MAX));
      out.extent = p.patch_extent;
      out.spread = p.patch_spread;
      out.angle = p.patch_angle;
    }
  }
  if (n < list.size())
    fail(PROX_ERROR_CAPACITY, "capacity " + std::to_string(capacity) + " is less than the " +
                                  std::to_string(list.size()) + " contacts (*count says how many)");
}

}  // namespace

extern "C" {

proxBodyDef proxDefaultBodyDef(void) {
  proxBodyDef d{};
  d.type = PROX_BODY_STATIC;
  d.pose.rotation.w = 1.0;
  d.toolMode = PROX_TOOL_FREE;
  const coupling::CouplingSettings c;
  d.couplingStiffness = c.linear_stiffness;
  d.couplingDamping = c.linear_damping;
  d.couplingAngularStiffness = c.angular_stiffness;
  d.couplingAngularDamping = c.angular_damping;
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateBody(proxWorldId world, const proxBodyDef* def, proxBodyId* body) {
  return guard("proxWorld_CreateBody", [&] {
    need(body, "body");
    *body = proxBodyId{};
    runtime::World& w = world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultBodyDef");
    runtime::World* mesh_world = nullptr;
    const runtime::Handle mesh = mesh_of(def->mesh, mesh_world);
    if (mesh_world != &w) fail(PROX_ERROR_INVALID_HANDLE, "def->mesh belongs to another world");
    runtime::BodyType type;
    switch (enum_value(def->type)) {
      case PROX_BODY_STATIC:
        type = runtime::BodyType::Static;
        break;
      case PROX_BODY_MOVABLE:
        type = runtime::BodyType::Movable;
        break;
      case PROX_BODY_TOOL:
        type = runtime::BodyType::Tool;
        break;
      default:
        fail(PROX_ERROR_INVALID_ARGUMENT, "def->type is not a proxBodyType");
    }
    const Pose pose = to_pose(def->pose, "def->pose");
    const Vec3 reference = to_vec(def->referencePoint, "def->referencePoint");
    runtime::ToolSettings tool;
    switch (enum_value(def->toolMode)) {
      case PROX_TOOL_FREE:
        break;
      case PROX_TOOL_CONSTRAINED:
        if (type != runtime::BodyType::Tool)
          fail(PROX_ERROR_INVALID_ARGUMENT,
               "def->toolMode is PROX_TOOL_CONSTRAINED but def->type is not PROX_BODY_TOOL");
        tool.mode = coupling::ToolMode::Constrained;
        need_positive(def->couplingStiffness, "def->couplingStiffness");
        need_positive(def->couplingAngularStiffness, "def->couplingAngularStiffness");
        need_non_negative(def->couplingDamping, "def->couplingDamping");
        need_non_negative(def->couplingAngularDamping, "def->couplingAngularDamping");
        tool.coupling = {def->couplingStiffness, def->couplingDamping, def->couplingAngularStiffness,
                         def->couplingAngularDamping};
        break;
      default:
        fail(PROX_ERROR_INVALID_ARGUMENT, "def->toolMode is not a proxToolMode");
    }
    const runtime::Handle h = w.create_body(mesh, type, pose, reference, tool);
    *body = {h.index + 1, h.generation, world};
  });
}

proxResult proxBody_Destroy(proxBodyId body) {
  return guard("proxBody_Destroy", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = body_of(body, w);
    w->destroy_body(h);
  });
}

proxBool proxBody_IsValid(proxBodyId body) {
  return valid("proxBody_IsValid", [&] {
    runtime::World* w = nullptr;
    body_of(body, w);
  });
}

proxResult proxBody_SetPose(proxBodyId body, const proxPose* pose) {
  return guard("proxBody_SetPose", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = body_of(body, w);
    need(pose, "pose");
    const Pose p = to_pose(*pose, "pose");
    if (w->type(h) == runtime::BodyType::Static)
      fail(PROX_ERROR_INVALID_ARGUMENT, "body is static; create it PROX_BODY_MOVABLE to move it");
    if (w->running() && w->device(h).attached())
      fail(PROX_ERROR_BUSY, "body is a tool held by a device while the threads run; the device moves it");
    w->set_pose(h, p);
  });
}

proxResult proxBody_GetPose(proxBodyId body, proxPose* pose) {
  return guard("proxBody_GetPose", [&] {
    need(pose, "pose");
    runtime::World* w = nullptr;
    const runtime::Handle h = body_of(body, w);
    *pose = to_c(w->current_pose(h));
  });
}

proxResult proxBody_GetProxyPose(proxBodyId tool, proxPose* pose) {
  return guard("proxBody_GetProxyPose", [&] {
    need(pose, "pose");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    *pose = to_c(w->proxy_pose(h));
  });
}

proxResult proxBody_GetContacts(proxBodyId tool, proxContact* contacts, int32_t capacity, int32_t* count) {
  return guard("proxBody_GetContacts",
               [&] { copy_contacts(tool, contacts, nullptr, capacity, count, true); });
}

proxResult proxBody_GetContactPatches(proxBodyId tool, proxContact* contacts, proxContactPatch* patches,
                                      int32_t capacity, int32_t* count) {
  return guard("proxBody_GetContactPatches",
               [&] { copy_contacts(tool, contacts, patches, capacity, count, false); });
}

proxResult proxBody_GetWrench(proxBodyId tool, proxWrench* wrench) {
  return guard("proxBody_GetWrench", [&] {
    need(wrench, "wrench");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    const Wrench x = w->wrench(h);
    *wrench = {to_c(x.force), to_c(x.torque), x.clipped ? 1 : 0};
  });
}

proxResult proxBody_GetIntersections(proxBodyId tool, proxVec3* points, int32_t pointCapacity,
                                     int32_t* pointCount, proxPolylineInfo* lines, int32_t lineCapacity,
                                     int32_t* lineCount) {
  return guard("proxBody_GetIntersections", [&] {
    need(pointCount, "pointCount");
    need(lineCount, "lineCount");
    *pointCount = 0;
    *lineCount = 0;
    if (pointCapacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "pointCapacity is negative");
    if (lineCapacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "lineCapacity is negative");
    if (pointCapacity > 0) need(points, "points");
    if (lineCapacity > 0) need(lines, "lines");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    std::vector<std::pair<std::uint32_t, Polyline>> found;
    w->intersections(h, found);
    int32_t point_total = 0;
    for (const auto& entry : found) point_total += static_cast<int32_t>(entry.second.points.size());
    *pointCount = point_total;
    *lineCount = static_cast<int32_t>(found.size());
    int32_t next = 0;
    bool fits = true;
    for (std::size_t i = 0; i < found.size(); ++i) {
      const Polyline& line = found[i].second;
      const auto n = static_cast<int32_t>(line.points.size());
      if (static_cast<int32_t>(i) < lineCapacity)
        lines[i] = {{found[i].first + 1, w->body_generation(found[i].first), tool.world},
                    next,
                    n,
                    line.closed ? 1 : 0,
                    0};
      else
        fits = false;
      for (int32_t k = 0; k < n; ++k) {
        if (next + k < pointCapacity)
          points[next + k] = to_c(line.points[static_cast<std::size_t>(k)]);
        else
          fits = false;
      }
      next += n;
    }
    if (!fits)
      fail(PROX_ERROR_CAPACITY, "the " + std::to_string(*lineCount) + " polylines with " +
                                    std::to_string(*pointCount) + " points do not fit in capacities " +
                                    std::to_string(lineCapacity) + " and " + std::to_string(pointCapacity));
  });
}

}  // extern "C"
