// Meshes: from arrays, files or files' bytes in memory (OBJ, glTF), their information.
#include "capi/common.h"
#include "capi/rig.h"

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
#include <string>
#include <vector>

using namespace prox;
using namespace prox::capi;

namespace {

proxMeshId make_mesh_id(proxWorldId world, runtime::Handle h) { return {h.index + 1, h.generation, world}; }

#if PROX_WITH_GLTF
// Records what loading `mesh` skipped, for proxMesh_GetWarnings (only the
// glTF reader skips anything).
void keep_warnings(runtime::World& world, const proxMeshId& mesh, const std::vector<std::string>& warnings) {
  if (warnings.empty()) return;
  std::string text;
  for (const std::string& w : warnings) text += w + "\n";
  world.set_mesh_warnings({mesh.index1 - 1, mesh.generation}, std::move(text));
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

constexpr uint64_t kMaxMemoryMesh = uint64_t{1} << 32;

// The format of `name` by its extension, lower case ("obj", "gltf", "glb").
std::string extension_of(const std::string& name) {
  const std::size_t dot = name.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// A mesh from the file `name`, or, when `bytes` is given, from that file's
// `size` bytes already in memory (then a GLB is also known by its magic, and
// a .gltf's buffers must be embedded: nothing is read from disk). The bytes
// are copied once, into what the reader parses.
proxMeshId load_mesh(proxWorldId world, runtime::World& w, const std::string& name,
                     const unsigned char* bytes = nullptr, std::size_t size = 0) {
  std::string ext = extension_of(name);
  if (bytes && size >= 4 && std::memcmp(bytes, "glTF", 4) == 0) ext = "glb";
  if (ext == "obj") {
    io::ObjData obj;
    check(bytes ? io::parse_obj(std::string(reinterpret_cast<const char*>(bytes), size), name, obj)
                : io::read_obj(name, obj));
    return add_mesh(world, w,
                    {obj.positions.data(), static_cast<uint32_t>(obj.positions.size() / 3),
                     obj.indices.data(), static_cast<uint32_t>(obj.indices.size() / 3)},
                    name);
  }
#if PROX_WITH_GLTF
  if (ext == "gltf" || ext == "glb") {
    std::vector<io::GltfMesh> parts;
    std::vector<std::string> warnings;
    io::GltfLoadOptions options;
    options.external_buffers = bytes == nullptr;
    check(bytes ? io::load_gltf_bytes({bytes, bytes + size}, name, options, parts, &warnings)
                : io::load_gltf(name, options, parts, &warnings));
    if (parts.empty()) fail(PROX_ERROR_INVALID_MESH, name + ": the scene has no triangles");
    const io::GltfMesh& m = parts.front();
    const proxMeshId id = add_mesh(world, w,
                                   {m.positions.data(), static_cast<uint32_t>(m.positions.size() / 3),
                                    m.indices.data(), static_cast<uint32_t>(m.indices.size() / 3)},
                                   name);
    if (m.rig) attach_rig(w, id, m.rig);
    keep_warnings(w, id, warnings);
    return id;
  }
#endif
  fail(PROX_ERROR_UNSUPPORTED,
       name + ": unsupported file type '." + ext + "' (.obj, .gltf and .glb are read)");
}

}  // namespace

extern "C" {

proxMeshDef proxDefaultMeshDef(void) {
  proxMeshDef d{};
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateMesh(proxWorldId world, const proxMeshDef* def, proxMeshId* mesh) {
  return guard("proxWorld_CreateMesh", [&] {
    need(mesh, "mesh");
    *mesh = proxMeshId{};
    runtime::World& w = world_of(world);
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
    need(path, "path");
    *mesh = load_mesh(world, w, path);
  });
}

proxResult proxWorld_LoadMeshFromMemory(proxWorldId world, const void* data, uint64_t size, const char* name,
                                        proxMeshId* mesh) {
  return guard("proxWorld_LoadMeshFromMemory", [&] {
    need(mesh, "mesh");
    *mesh = proxMeshId{};
    runtime::World& w = world_of(world);
    need(name, "name");
    if (size == 0) fail(PROX_ERROR_INVALID_ARGUMENT, std::string(name) + ": size is 0 (no bytes to read)");
    need(data, "data");
    if (size > kMaxMemoryMesh)
      fail(PROX_ERROR_INVALID_ARGUMENT, std::string(name) + ": " + std::to_string(size) +
                                            " bytes, more than the 4 GiB a mesh file may have");
    *mesh =
        load_mesh(world, w, name, static_cast<const unsigned char*>(data), static_cast<std::size_t>(size));
  });
}

proxResult proxMesh_Destroy(proxMeshId mesh) {
  return guard("proxMesh_Destroy", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    Status s;
    if (!w->destroy_mesh(h, s)) fail(PROX_ERROR_INVALID_ARGUMENT, s.message());
  });
}

proxBool proxMesh_IsValid(proxMeshId mesh) {
  return valid("proxMesh_IsValid", [&] {
    runtime::World* w = nullptr;
    mesh_of(mesh, w);
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

proxResult proxMesh_SetVertices(proxMeshId mesh, const double* positions, uint32_t vertexCount) {
  return guard("proxMesh_SetVertices", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    need(positions, "positions");
    Status s;
    if (!w->set_vertices(h, positions, vertexCount, s)) fail(PROX_ERROR_INVALID_ARGUMENT, s.message());
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
    const runtime::Handle h = mesh_of(mesh, w);
    std::string text = w->mesh_warnings(h);
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
