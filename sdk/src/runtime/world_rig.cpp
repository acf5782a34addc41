// World's glTF rigs: which mesh has one, and its deformations replacing the
// mesh's vertices.
#include "runtime/world.h"

namespace prox::runtime {

bool World::set_rig(Handle mesh, std::shared_ptr<const rig::Rig> rig, Status& status) {
  if (!rig) {
    rigs_.erase(mesh.index);
    status = Status::ok();
    return true;
  }
  const Mesh& m = this->mesh(mesh);
  if (m.input_vertex_count() != rig->vertex_count) {
    status = Status(StatusCode::InvalidArgument, "the rig has " + std::to_string(rig->vertex_count) +
                                                     " vertices but the mesh was built from " +
                                                     std::to_string(m.input_vertex_count()));
    return false;
  }
  rigs_.insert_or_assign(mesh.index, MeshRig(std::move(rig)));
  status = Status::ok();
  return true;
}

const MeshRig* World::rig(Handle mesh) const {
  const auto it = rigs_.find(mesh.index);
  return it == rigs_.end() ? nullptr : &it->second;
}

MeshRig* World::rig(Handle mesh) {
  const auto it = rigs_.find(mesh.index);
  return it == rigs_.end() ? nullptr : &it->second;
}

}  // namespace prox::runtime
