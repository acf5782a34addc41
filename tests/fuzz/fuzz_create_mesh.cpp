// proxWorld_CreateMesh from fuzzed vertex and index arrays (NaN, infinite,
// huge, denormal, repeated, out of range), then, when it is accepted, the
// mesh as a static body and as a tool beside it through a step, tracking,
// contacts, intersections and a distance: every failure is named, every
// number that comes back is finite.
#include "check.h"
#include "fuzz_input.h"

#include <proxima/proxima.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

void expect_named(proxResult r, const char* call) {
  PROX_FUZZ_CHECK(r <= 0, "%s returned %d", call, r);
  if (r != PROX_SUCCESS)
    PROX_FUZZ_CHECK(proxGetLastError()[0] != '\0' && std::strstr(proxResultString(r), "unknown") == nullptr,
                    "%s failed (%d) without a message", call, r);
}

bool finite(const proxVec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

using prox::fuzz::set_enum;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  prox::fuzz::Input in(data, size);
  const std::uint32_t vertex_count = in.below(48);
  const std::uint32_t triangle_count = in.below(48);
  std::vector<double> positions;
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    const std::uint8_t how = in.u8();
    if (v > 0 && how % 8 == 0) {  // a repeated vertex
      const std::size_t from = 3 * (in.below(v));
      positions.insert(positions.end(), {positions[from], positions[from + 1], positions[from + 2]});
    } else {
      for (int c = 0; c < 3; ++c) positions.push_back(in.number());
    }
  }
  std::vector<std::uint32_t> indices;
  for (std::uint32_t k = 0; k < 3 * triangle_count; ++k) {
    const std::uint8_t how = in.u8();
    indices.push_back(how % 16 == 0 ? in.u32() : in.below(vertex_count > 0 ? vertex_count : 1));
  }
  const std::uint8_t shape = in.u8();  // counts that disagree with the arrays, null pointers

  proxWorldDef world_def = proxDefaultWorldDef();
  set_enum(world_def.method, shape % 3);
  proxWorldId world;
  PROX_FUZZ_CHECK(proxCreateWorld(&world_def, &world) == PROX_SUCCESS, "%s", proxGetLastError());

  proxMeshDef def = proxDefaultMeshDef();
  def.positions = (shape & 8) ? nullptr : positions.data();
  def.vertexCount = vertex_count;
  def.indices = (shape & 16) ? nullptr : indices.data();
  def.triangleCount = triangle_count;
  proxMeshId mesh;
  proxResult r = proxWorld_CreateMesh(world, &def, &mesh);
  expect_named(r, "proxWorld_CreateMesh");
  if (r == PROX_SUCCESS) {
    proxMeshInfo info;
    PROX_FUZZ_CHECK(proxMesh_GetInfo(mesh, &info) == PROX_SUCCESS, "%s", proxGetLastError());
    PROX_FUZZ_CHECK(info.triangleCount >= 1 && info.triangleCount <= triangle_count, "%u triangles of %u",
                    info.triangleCount, triangle_count);
    PROX_FUZZ_CHECK(finite(info.boundsMin) && finite(info.boundsMax), "non-finite bounds");

    proxBodyDef body = proxDefaultBodyDef();
    body.mesh = mesh;
    body.type = PROX_BODY_STATIC;
    proxBodyId rock, tool;
    PROX_FUZZ_CHECK(proxWorld_CreateBody(world, &body, &rock) == PROX_SUCCESS, "%s", proxGetLastError());
    body.type = PROX_BODY_TOOL;
    // Beside the first: a fraction of its size (possibly zero, possibly
    // overflowing: the pose check must say so).
    const double width = info.boundsMax.x - info.boundsMin.x;
    body.pose.position.x = width * static_cast<double>(in.u8()) / 128.0;
    r = proxWorld_CreateBody(world, &body, &tool);
    expect_named(r, "proxWorld_CreateBody");
    if (r == PROX_SUCCESS) {
      expect_named(proxWorld_Step(world), "proxWorld_Step");
      proxContact contacts[16];
      int32_t count = 0;
      r = proxBody_GetContacts(tool, contacts, 16, &count);
      PROX_FUZZ_CHECK(r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY, "%s", proxGetLastError());
      for (int32_t i = 0; i < (count < 16 ? count : 16); ++i)
        PROX_FUZZ_CHECK(std::isfinite(contacts[i].distance) && contacts[i].distance >= 0 &&
                            finite(contacts[i].pointTool) && finite(contacts[i].normal),
                        "contact %d: distance %g", i, contacts[i].distance);
      proxWrench wrench;
      PROX_FUZZ_CHECK(proxBody_GetWrench(tool, &wrench) == PROX_SUCCESS, "%s", proxGetLastError());
      PROX_FUZZ_CHECK(finite(wrench.force) && finite(wrench.torque), "non-finite wrench");
      proxPose moved = body.pose;
      moved.position.x *= 0.5;
      expect_named(proxBody_SetPose(tool, &moved), "proxBody_SetPose");
      expect_named(proxWorld_Track(world), "proxWorld_Track");
      int32_t points = 0, lines = 0;
      proxVec3 point_buffer[32];
      proxPolylineInfo line_buffer[8];
      r = proxBody_GetIntersections(tool, point_buffer, 32, &points, line_buffer, 8, &lines);
      PROX_FUZZ_CHECK(r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY, "%s", proxGetLastError());
      double distance = 0;
      expect_named(proxBody_GetDistance(tool, rock, HUGE_VAL, &distance), "proxBody_GetDistance");
      PROX_FUZZ_CHECK(std::isfinite(distance) && distance >= 0, "distance %g", distance);
    }
  }
  PROX_FUZZ_CHECK(proxWorld_Destroy(world) == PROX_SUCCESS, "%s", proxGetLastError());
  return 0;
}
