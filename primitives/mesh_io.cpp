#include "mesh_io.h"

namespace lucent {

// Placeholder until the CGAL reader lands: refuse clearly rather than pretend.
std::shared_ptr<MeshData> loadMeshFile(const std::string&) {
  throw MeshError("mesh files are not supported yet");
}

void finishMesh(MeshData& mesh) {
  if (mesh.triangles.empty()) throw MeshError("the mesh has no triangles");
  mesh.closed = false;
}

}  // namespace lucent
