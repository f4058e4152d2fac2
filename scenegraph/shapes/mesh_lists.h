// An inline mesh's lists as written (positions, indices, and optional normals and uvs,
// checked as <mesh> checks them), without the repairs of loading: the faces in their order
// and orientation, as a mesh camera takes them (render/mesh_camera.h).
#pragma once

#include "scenegraph/attribute_input.h"

#include "primitives/mesh_data.h"

#include <memory>

namespace lucent {

// Null, with the error reported to `in`, when a list is missing or wrong.
std::shared_ptr<const MeshData> readMeshLists(AttributeInput& in);

}  // namespace lucent
