// Meshes: from arrays or files (OBJ, glTF), their information.
#include "capi/common.h"

#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif

#include <cctype>

using namespace prox;
using namespace prox::capi;

namespace {

proxMeshId make_mesh_id(proxWorldId world, runtime::Handle h) { return {h.index + 1, h.generation, world}; }

// `source`: the file the data came from, named in the error when it is not
// a valid mesh.
proxMeshId add_mesh(proxWorldId world_id, runtime::World& world, const MeshInput& input,
                    const std::string& source = "") {
  Status status;
  const runtime::Handle h = world.create_mesh(input, status);
  if (!status && !source.empty()) fail(status_code(status), source + ": " + status.message());
  check(status);
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
      check(io::load_gltf(p, io::GltfLoadOptions{}, parts));
      if (parts.empty()) fail(PROX_ERROR_INVALID_MESH, p + ": the scene has no triangles");
      const io::GltfMesh& m = parts.front();
      *mesh = add_mesh(world, w,
                       {m.positions.data(), static_cast<uint32_t>(m.positions.size() / 3), m.indices.data(),
                        static_cast<uint32_t>(m.indices.size() / 3)},
                       p);
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

}  // extern "C"
