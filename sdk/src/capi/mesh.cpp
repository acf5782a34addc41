// Meshes: from arrays or files (OBJ, glTF), their information.
#include "capi/common.h"

#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>

using namespace prox;
using namespace prox::capi;

namespace {

proxMeshId make_mesh_id(proxWorldId world, runtime::Handle h) { return {h.index + 1, h.generation, world}; }

uint64_t warnings_key(const proxMeshId& mesh) { return uint64_t{mesh.index1 - 1} << 32 | mesh.generation; }

#if PROX_WITH_GLTF
// Records what loading `mesh` skipped, for proxMesh_GetWarnings (only the
// glTF reader skips anything).
void keep_warnings(const proxMeshId& mesh, const std::vector<std::string>& warnings) {
  if (warnings.empty()) return;
  std::string text;
  for (const std::string& w : warnings) text += w + "\n";
  std::lock_guard<std::mutex> lock(g_worlds_mutex);
  g_worlds[mesh.world.index1 - 1].mesh_warnings[warnings_key(mesh)] = std::move(text);
}
#endif

// `source`: the file the data came from, named in the error when it is not
// a valid mesh.
proxMeshId add_mesh(proxWorldId world_id, runtime::World& world, const MeshInput& input,
                    const std::string& source = "") {
  Status status;
  const runtime::Handle h = world.create_mesh(input, status);
  if (!status && !source.empty()) fail(status_code(status), source + ": " + status.message());
  check(status);
  // Checked on the built mesh's bounds (the mesh layer accepts any finite
  // coordinate; the distance kernel does not).
  const Aabb& box = world.mesh(h).bounds();
  for (const double x : {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z})
    if (std::abs(x) > kMaxCoordinate) {
      Status ignored;
      world.destroy_mesh(h, ignored);
      char value[32];
      std::snprintf(value, sizeof value, "%g", x);
      fail(PROX_ERROR_INVALID_MESH, (source.empty() ? "" : source + ": ") + "a vertex has a coordinate of " +
                                        value + ", beyond the +-1e50 Proxima supports");
    }
  return make_mesh_id(world_id, h);
}

}  // namespace

extern "C" {

proxMeshDef proxDefaultMeshDef(void) {
  proxMeshDef d{};
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateMesh(proxWorldId world, const proxMeshDef* def, proxMeshId* mesh) {
  return guard("proxWorld_CreateMesh", [&] {
    need(mesh, "mesh");
    *mesh = proxMeshId{};
    runtime::World& w = world_of(world);
    need_stopped(w);
    need(def, "def");
    need_def(*def, "proxDefaultMeshDef");
    *mesh = add_mesh(world, w, {def->positions, def->vertexCount, def->indices, def->triangleCount});
  });
}

proxResult proxWorld_LoadMesh(proxWorldId world, const char* path, proxMeshId* mesh) {
  return guard("proxWorld_LoadMesh", [&] {
    need(mesh, "mesh");
    *mesh = proxMeshId{};
    runtime::World& w = world_of(world);
    need_stopped(w);
    need(path, "path");
    std::string p(path);
    std::string ext = p.substr(p.find_last_of('.') == std::string::npos ? p.size() : p.find_last_of('.') + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "obj") {
      io::ObjData obj;
      check(io::read_obj(p, obj));
      *mesh = add_mesh(world, w,
                       {obj.positions.data(), static_cast<uint32_t>(obj.positions.size() / 3),
                        obj.indices.data(), static_cast<uint32_t>(obj.indices.size() / 3)},
                       p);
      return;
    }
#if PROX_WITH_GLTF
    if (ext == "gltf" || ext == "glb") {
      std::vector<io::GltfMesh> parts;
      std::vector<std::string> warnings;
      check(io::load_gltf(p, io::GltfLoadOptions{}, parts, &warnings));
      if (parts.empty()) fail(PROX_ERROR_INVALID_MESH, p + ": the scene has no triangles");
      const io::GltfMesh& m = parts.front();
      *mesh = add_mesh(world, w,
                       {m.positions.data(), static_cast<uint32_t>(m.positions.size() / 3), m.indices.data(),
                        static_cast<uint32_t>(m.indices.size() / 3)},
                       p);
      keep_warnings(*mesh, warnings);
      return;
    }
#endif
    fail(PROX_ERROR_UNSUPPORTED,
         p + ": unsupported file type '." + ext + "' (.obj, .gltf and .glb are read)");
  });
}

proxResult proxMesh_Destroy(proxMeshId mesh) {
  return guard("proxMesh_Destroy", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    need_stopped(*w);
    Status s;
    if (!w->destroy_mesh(h, s)) fail(PROX_ERROR_INVALID_ARGUMENT, s.message());
    std::lock_guard<std::mutex> lock(g_worlds_mutex);
    g_worlds[mesh.world.index1 - 1].mesh_warnings.erase(warnings_key(mesh));
  });
}

proxResult proxMesh_GetInfo(proxMeshId mesh, proxMeshInfo* info) {
  return guard("proxMesh_GetInfo", [&] {
    need(info, "info");
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const Mesh& m = w->mesh(h);
    const MeshStats& s = m.stats();
    *info = proxMeshInfo{s.triangles,         s.vertices,           s.dropped_triangles, s.boundary_edges,
                         s.nonmanifold_edges, to_c(m.bounds().min), to_c(m.bounds().max)};
  });
}

proxResult proxMesh_GetTriangles(proxMeshId mesh, double* positions, uint32_t vertexCapacity,
                                 uint32_t* vertexCount, uint32_t* indices, uint32_t triangleCapacity,
                                 uint32_t* triangleCount) {
  return guard("proxMesh_GetTriangles", [&] {
    need(vertexCount, "vertexCount");
    need(triangleCount, "triangleCount");
    *vertexCount = 0;
    *triangleCount = 0;
    if (vertexCapacity > 0 && positions == nullptr)
      fail(PROX_ERROR_INVALID_ARGUMENT, "positions is NULL but vertexCapacity is > 0");
    if (triangleCapacity > 0 && indices == nullptr)
      fail(PROX_ERROR_INVALID_ARGUMENT, "indices is NULL but triangleCapacity is > 0");
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const Mesh& m = w->mesh(h);
    *vertexCount = m.vertex_count();
    *triangleCount = m.triangle_count();
    if (vertexCapacity < m.vertex_count() || triangleCapacity < m.triangle_count())
      fail(PROX_ERROR_CAPACITY, "the mesh has " + std::to_string(m.vertex_count()) + " vertices and " +
                                    std::to_string(m.triangle_count()) + " triangles; the capacities are " +
                                    std::to_string(vertexCapacity) + " and " +
                                    std::to_string(triangleCapacity));
    for (uint32_t v = 0; v < m.vertex_count(); ++v) {
      const Vec3& p = m.vertex(v);
      positions[3 * v] = p.x;
      positions[3 * v + 1] = p.y;
      positions[3 * v + 2] = p.z;
    }
    for (uint32_t t = 0; t < m.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k) indices[3 * t + k] = m.indices(t)[k];
  });
}

proxResult proxMesh_GetWarnings(proxMeshId mesh, char* buffer, int32_t capacity, int32_t* length) {
  return guard("proxMesh_GetWarnings", [&] {
    need(length, "length");
    *length = 0;
    if (capacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "capacity is negative");
    if (capacity > 0 && buffer == nullptr)
      fail(PROX_ERROR_INVALID_ARGUMENT, "buffer is NULL but capacity is > 0");
    runtime::World* w = nullptr;
    mesh_of(mesh, w);
    std::string text;
    {
      std::lock_guard<std::mutex> lock(g_worlds_mutex);
      const auto& warnings = g_worlds[mesh.world.index1 - 1].mesh_warnings;
      const auto it = warnings.find(warnings_key(mesh));
      if (it != warnings.end()) text = it->second;
    }
    if (text.size() > static_cast<std::size_t>(INT32_MAX - 1)) text.resize(INT32_MAX - 1);
    *length = static_cast<int32_t>(text.size());
    if (capacity == 0) {
      if (!text.empty())
        fail(PROX_ERROR_CAPACITY, "the warnings need " + std::to_string(text.size() + 1) + " bytes");
      return;
    }
    const std::size_t fits = std::min(text.size(), static_cast<std::size_t>(capacity) - 1);
    std::memcpy(buffer, text.data(), fits);
    buffer[fits] = '\0';
    if (fits < text.size())
      fail(PROX_ERROR_CAPACITY, "the warnings need " + std::to_string(text.size() + 1) +
                                    " bytes; capacity is " + std::to_string(capacity));
  });
}

}  // extern "C"
