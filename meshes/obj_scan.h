// A walk over an OBJ file before CGAL reads it. CGAL 5.5's OBJ reader keeps only positions
// and faces, stores an out-of-range or zero index as is, reads tab-separated face corners
// wrongly, and refuses the whole file at a polyline ('l') statement. The walk checks every
// statement CGAL reads (with the line number in the message), neutralises what a renderer
// ignores (polylines, a UTF-8 byte-order mark, tabs) in the buffer CGAL will read, and keeps
// what CGAL drops: vertex normals (vn) and texture coordinates (vt) with, for every corner of
// every face, which of them it uses. Faces are kept in file order, so face i here is polygon i
// of CGAL's soup.
#pragma once

#include "primitives/math.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lucent {

struct ObjScan {
  std::size_t vertexCount = 0;  // 'v' statements
  std::vector<Vec2> texcoords;  // 'vt' (u, v), in file order
  std::vector<Vec3> normals;    // 'vn', normalised, in file order
  // Corners of face f are corners[faceStart[f] .. faceStart[f + 1]); each names the 0-based
  // texcoord and normal it uses, or -1.
  struct Corner {
    int32_t texcoord = -1;
    int32_t normal = -1;
  };
  std::vector<uint32_t> faceStart{0};
  std::vector<Corner> corners;
  bool everyCornerHasNormal = true;
  bool everyCornerHasTexcoord = true;

  std::size_t faceCount() const { return faceStart.size() - 1; }
};

// Checks `bytes` and edits it in place (see above); throws MeshError with a line number.
ObjScan scanObj(std::string& bytes);

}  // namespace lucent
