// A mesh camera as POV-Ray's mesh_camera block (render/mesh_camera.h has its rules).
// Lucent's coordinates are written unchanged (as every camera's), so POV-Ray's face normal,
// (P3 − P1) × (P2 − P1) in its left-handed reading, is Lucent's (b − a) × (c − a) when each
// face is written a, c, b. The camera's transform is carried into each mesh's matrix:
// POV-Ray's mesh camera ignores its camera's transforms, save for the location's and
// direction's z, which say the offset and the reverse.
#pragma once

#include "pov_writer.h"

#include "scenegraph/camera.h"

namespace lucent {

void writeMeshCamera(const Camera& camera, PovWriter& out, PovIssues& issues);

}  // namespace lucent
