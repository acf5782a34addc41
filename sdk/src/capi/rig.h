// glTF rigs at the C API: the loader hands a rigged mesh's rig to the world
// (capi/rig.cpp). Private to sdk/src/capi.
#pragma once

#include "capi/common.h"
#include "mesh/rig.h"

#include <memory>

namespace prox::capi {

// Keeps `rig` with the mesh `id` just made from its vertices; fails (the
// mesh destroyed) if they do not fit, which would be a bug.
void attach_rig(runtime::World& world, const proxMeshId& id, std::shared_ptr<const rig::Rig> rig);

}  // namespace prox::capi
