// POV-Ray 3.7's pavements of triangles and of hexagons (3 and 6 sides; pavement.cpp has the
// squares). The plane is cut into equilateral triangles of side 1 in rows sqrt(3)/2 high;
// each is folded onto the upright triangle (0, 0), (1, 0), (1/2, sqrt(3)/2) (a downward
// one by a half turn), its whole coordinates finding its flags in the arrangement's block.
// Flags: 0x01, 0x02, 0x04 the left, right and bottom edges on a tile's border; a vertex where
// the tile turns inwards is one whose two edges are not border and whose 0x80 is clear (or,
// in hexagon pavements, whose own flag 0x4000 top, 0x2000 left, 0x1000 right is set); pairs
// of higher flags (0x100 to 0x400 with 0x10 to 0x40) mark cells whose border the form draws.
#include "pavement.h"
#include "pavement_layouts.h"

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

constexpr double kS3 = 1.7320508075688772935;    // sqrt(3)
constexpr double kS3h = 0.86602540378443864676;  // sqrt(3) / 2

struct Cell {
  long xv, zv;  // the triangle's whole coordinates
  double x, z;  // the point in the upright triangle
};

// POV-Ray's fold: a rectangle 1 by sqrt(3) holds two rows of triangles; the upper row moves
// down by half a side, and the point in a neighbour of the upright triangle turns onto it.
Cell foldTriangle(double px, double pz) {
  Cell c;
  c.xv = pavement::cellIndex(std::floor(px));
  c.zv = pavement::cellIndex(std::floor(pz / kS3));
  double x = px - static_cast<double>(c.xv);
  double z = pz - kS3 * static_cast<double>(c.zv);
  c.zv *= 2;
  c.xv *= 2;
  if (z > kS3h) {
    z -= kS3h;
    if (x > 0.5) {
      x -= 0.5;
      c.xv++;
    } else {
      x += 0.5;
      c.xv--;
    }
    c.zv++;
  }
  if (x == 0.0 || z / x > kS3) {
    z = kS3h - z;
    x = 0.5 - x;
    c.xv--;
  }
  if (x == 1.0 || z / (1.0 - x) > kS3) {
    z = kS3h - z;
    x = 1.5 - x;
    c.xv++;
  }
  c.x = x;
  c.z = z;
  return c;
}

double distance(double x, double z, double cx, double cz) {
  const double dx = x - cx, dz = z - cz;
  return std::sqrt(dx * dx + dz * dz);
}

// The three lines from the vertices to the middles of the opposite sides split the triangle
// into the parts nearest each vertex; these measures say which part the point is in.
struct Parts {
  double d1, d2, d3;
};
Parts parts(double x, double z) {
  return {1.0 - std::fabs(kS3 * z + x), 1.0 - std::fabs(kS3 * z - x + 1.0), 1.0 - x * 2.0};
}

// Inner corners: at each vertex where the tile turns, the interior modifier's shape.
double interiorCorners(unsigned how, int interior, double x, double z, double v) {
  const bool top = (how & 0x83) == 0 || (how & 0x4000);
  const bool left = (how & 0x85) == 0 || (how & 0x2000);
  const bool right = (how & 0x86) == 0 || (how & 0x1000);
  if (interior == 1) {
    const Parts p = parts(x, z);
    const double a = std::fabs(kS3 * z + x), b = std::fabs(kS3 * z - x + 1.0);
    if (top && p.d1 < 0 && p.d2 < 0) v = std::max(v, std::min(1.5 * a - 2.0, 1.5 * b - 2.0));
    if (left && p.d1 > 0 && p.d3 > 0) v = std::max(v, std::min(1.0 - 1.5 * a, 1.0 - x * 3.0));
    if (right && p.d3 < 0 && p.d2 > 0) v = std::max(v, std::min(1.0 - 1.5 * b, x * 3.0 - 2.0));
  } else if (interior == 2) {
    if (top) v = std::max(v, 1.0 - distance(x, z, 0.5, kS3h) * 3.0);
    if (left) v = std::max(v, 1.0 - distance(x, z, 0.0, 0.0) * 3.0);
    if (right) v = std::max(v, 1.0 - distance(x, z, 1.0, 0.0) * 3.0);
  } else {
    if (top) v = std::max(v, 1.0 - (kS3h - z) * 2.0 * kS3);
    if (left) v = std::max(v, 1.0 - std::fabs(kS3 * x + z) * kS3);
    if (right) v = std::max(v, 1.0 - std::fabs(kS3 * (x - 1.0) - z) * kS3);
  }
  return v;
}

// Outer corners (triangles only): where two border edges meet, the exterior modifier's
// shape replaces the value near that vertex (POV-Ray sets it there rather than keeping the
// larger).
double exteriorCorners(unsigned how, int exterior, double x, double z, double v) {
  const double cx = x - 0.5, cz = z - kS3h / 3.0;
  if (exterior == 2) {
    const Parts p = parts(x, z);
    if (((how & 0x03) == 0x03 && p.d1 <= 0.0 && p.d2 <= 0.0) ||
        ((how & 0x06) == 0x06 && p.d2 >= 0.0 && p.d3 <= 0.0) ||
        ((how & 0x05) == 0x05 && p.d1 >= 0.0 && p.d3 >= 0.0))
      v = std::min(1.0, 2 * kS3 * std::sqrt(cx * cx + cz * cz));
  } else if (exterior == 1) {
    const double e1 = 1.0 - std::fabs(kS3 * x - z) * kS3;
    const double e2 = 1.0 - std::fabs(kS3 * (1.0 - x) - z) * kS3;
    const double e3 = 1.0 - z * 2.0 * kS3;
    if ((how & 0x03) == 0x03 && e1 >= 0.0 && e2 >= 0.0)
      v = std::min(1.0, std::fabs(cz * 2.0 * kS3));
    if ((how & 0x06) == 0x06 && e2 >= 0.0 && e3 >= 0.0)
      v = std::min(1.0, std::fabs(kS3 * cx - cz) * kS3);
    if ((how & 0x05) == 0x05 && e1 >= 0.0 && e3 >= 0.0)
      v = std::min(1.0, std::fabs(kS3 * cx + cz) * kS3);
  }
  return v;
}

// The form's cells: in the part of the triangle by one vertex, the border runs round another
// (form 2: an arc about it; form 1: a straight cut). False where no form applies.
bool triangleForm(unsigned how, int form, double x, double z, double& value) {
  if (form != 1 && form != 2) return false;
  const Parts p = parts(x, z);
  struct Turn {
    unsigned mask;
    bool in;        // the point is in the part the mask's turn concerns
    double cx, cz;  // the vertex an arc (form 2) turns about
    double cut;     // form 1's value
  };
  const Turn turns[] = {
      {0x120, p.d1 < 0 && p.d2 < 0, 0.0, 0.0, -p.d1 * 2},
      {0x140, p.d1 > 0 && p.d3 > 0, 0.5, kS3h, p.d1 * 2},
      {0x210, p.d1 < 0 && p.d2 < 0, 1.0, 0.0, -p.d2 * 2},
      {0x240, p.d3 < 0 && p.d2 > 0, 0.5, kS3h, p.d2 * 2},
      {0x410, p.d1 > 0 && p.d3 > 0, 1.0, 0.0, p.d3 * 2},
      {0x420, p.d3 < 0 && p.d2 > 0, 0.0, 0.0, -p.d3 * 2},
  };
  for (const Turn& t : turns) {
    if ((how & t.mask) != t.mask || !t.in) continue;
    if (form == 1) {
      value = std::min(t.cut, 1.0);
    } else {
      const double arc = 2.0 * kS3 * (distance(x, z, t.cx, t.cz) - kS3 / 3.0);
      value = std::min(std::max(arc, 0.0), 1.0);
    }
    return true;
  }
  return false;
}

}  // namespace

double pavementTrianglesValue(const PavementParams& params, const Vec3& point) {
  const Cell c = foldTriangle(point.x, point.z);
  const unsigned how = pavement::flagsAt(params.sides, params.tiles, params.number, c.xv, c.zv);
  const double x = c.x, z = c.z;
  double v = 0.0;
  if (how & 0x01) v = std::max(v, 1.0 - std::fabs(kS3 * x - z) * kS3);
  if (how & 0x02) v = std::max(v, 1.0 - std::fabs(kS3 * (1.0 - x) - z) * kS3);
  if (how & 0x04) v = std::max(v, 1.0 - z * 2.0 * kS3);
  v = interiorCorners(how, params.interior, x, z, v);
  if (params.sides == 3) v = exteriorCorners(how, params.exterior, x, z, v);
  double formed;
  if (triangleForm(how, params.form, x, z, formed)) return formed;
  return v;
}

}  // namespace lucent
