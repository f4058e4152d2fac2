// POV-Ray 3.7's pavement pattern (pattern.cpp, J. Grimbert's pavements), restated. The plane
// is cut into cells, unit squares (4 sides) or equilateral triangles of side 1 (3 sides, and
// 6: each hexagon is six triangles). A cell's whole coordinates find it in its arrangement's
// repeating block (pavement_layouts.cpp), whose flags say which of the cell's edges and
// corners are on a tile's border; the value is the largest of the measures those flags turn
// on: 1 on a border edge falling to 0 halfway across the cell, and at a border's corners the
// shape the exterior, interior and form modifiers give it. The arithmetic follows POV-Ray's
// step by step so that values agree to rounding.
#include "pavement.h"

#include "pavement_layouts.h"

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

// --- squares ------------------------------------------------------------------------------

// A square's corner c (0x10 (0, 1), 0x20 (1, 1), 0x40 (1, 0), 0x80 (0, 0)): twice the point's
// distances from it along x and z.
struct Corner {
  unsigned bit;
  bool atX1, atZ1;
};
constexpr Corner kSquareCorners[] = {
    {0x10, false, true}, {0x20, true, true}, {0x40, true, false}, {0x80, false, false}};

void cornerOffsets(const Corner& c, double x, double z, double& dx, double& dz) {
  dx = c.atX1 ? 2 - 2 * x : 2 * x;
  dz = c.atZ1 ? 2 - 2 * z : 2 * z;
}

// A turning cell (a corner flag with the two edges away from it): the tile's border bends
// round that corner, as form 0 (a sharp turn), 1 (cut) or 2 (rounded) draws it. False: no
// such cell or a form that draws none.
bool squareForm(unsigned how, int form, double x, double z, double& value) {
  if (form < 0 || form > 2) return false;
  // Each corner's turning mask: the corner's flag and the edges not touching it.
  constexpr unsigned kTurns[] = {0x16, 0x2C, 0x49, 0x83};
  for (int i = 0; i < 4; ++i) {
    if ((how & kTurns[i]) != kTurns[i]) continue;
    double dx, dz;
    cornerOffsets(kSquareCorners[i], x, z, dx, dz);
    if (form == 2) value = std::min(std::fabs(std::sqrt(dx * dx + dz * dz) - 1.0), 1.0);
    else if (form == 1) value = std::min(std::fabs(dx + dz - 1.0), 1.0);
    else value = std::max(std::max(dx - 1.0, dz - 1.0), std::min(1.0 - dx, 1.0 - dz));
    return true;
  }
  return false;
}

double squareValue(const PavementParams& p, unsigned how, double x, double z) {
  double v = 0.0;
  if (squareForm(how, p.form, x, z, v)) return v;
  if (how & 0x01) v = std::max(v, 2 * z - 1);
  if (how & 0x02) v = std::max(v, 2 * x - 1);
  if (how & 0x04) v = std::max(v, 1 - 2 * z);
  if (how & 0x08) v = std::max(v, 1 - 2 * x);
  for (const Corner& c : kSquareCorners) {  // inner corners of the tile
    if (!(how & c.bit)) continue;
    double dx, dz;
    cornerOffsets(c, x, z, dx, dz);
    if (p.interior == 2) v = std::max(v, 1.0 - std::sqrt(dx * dx + dz * dz));
    else if (p.interior == 1) v = std::max(v, 1.0 - (dx + dz));
    else v = std::max(v, std::min(1.0 - dx, 1.0 - dz));
  }
  // Outer corners: two border edges meeting at a corner of the cell.
  constexpr unsigned kPairs[] = {0x09, 0x03, 0x06, 0x0C};  // at (0,1), (1,1), (1,0), (0,0)
  for (int i = 0; i < 4 && p.exterior != 0; ++i) {
    if ((how & kPairs[i]) != kPairs[i]) continue;
    const Corner& c = kSquareCorners[i];
    if (p.exterior == 1) {
      double dx, dz;
      cornerOffsets(c, x, z, dx, dz);
      v = std::max(v, std::min(2.0 - (dx + dz), 1.0));
      continue;
    }
    const double u = 2 * x - 1, w = 2 * z - 1;
    if ((c.atX1 ? u >= 0 : u <= 0) && (c.atZ1 ? w >= 0 : w <= 0))
      v = std::max(v, std::min(std::sqrt(u * u + w * w), 1.0));
  }
  return v;
}

double squaresValue(const PavementParams& p, const Vec3& point) {
  const double x = point.x, z = point.z;
  const double fx = std::floor(x), fz = std::floor(z);
  const unsigned how = pavement::flagsAt(p.sides, p.tiles, p.number, pavement::cellIndex(fx),
                                         pavement::cellIndex(fz));
  return squareValue(p, how, x - fx, z - fz);
}

}  // namespace

int pavementCount(int sides, int tiles) { return pavement::layouts(sides, tiles).count; }

double pavementValue(const PavementParams& params, const Vec3& p) {
  if (params.sides == 4) return squaresValue(params, p);
  return pavementTrianglesValue(params, p);
}

}  // namespace lucent
