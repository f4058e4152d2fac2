// The height field's grid walk (primitives/height_field.h says the method and its sources).
#include "height_field.h"

#include "transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

constexpr double kRaw = 1.0 / 65536.0;  // POV-Ray's scale of a 16-bit height

// POV-Ray's face normal of three grid points in its raw space (x, h, z), unit, facing up
// (hfield.cpp, add_single_normal); false when a point lies off the grid.
bool addFaceNormal(const HeightMap& m, int x0, int z0, int x1, int z1, int x2, int z2, Vec3& sum) {
  const int xs = m.width - 1, zs = m.depth - 1;
  for (int v : {x0, x1, x2})
    if (v < 0 || v > xs) return false;
  for (int v : {z0, z1, z2})
    if (v < 0 || v > zs) return false;
  const Vec3 v0(x0, m.at(x0, z0), z0), v1(x1, m.at(x1, z1), z1), v2(x2, m.at(x2, z2), z2);
  Vec3 n = glm::cross(v2 - v0, v1 - v0);
  const double len = glm::length(n);
  n = len > 1e-10 ? n / len : Vec3(0.0, 1.0, 0.0);
  if (n.y < 0.0) n = -n;
  sum += n;
  return true;
}

}  // namespace

HeightField::HeightField(std::shared_ptr<const HeightMap> map, bool smooth, double waterLevel,
                         bool open)
    : map_(std::move(map)), smooth_(smooth), open_(open), water_(waterLevel) {
  if (!map_ || map_->width < 2 || map_->depth < 2 ||
      map_->values.size() != static_cast<size_t>(map_->width) * map_->depth)
    throw std::invalid_argument("HeightField: the grid must be at least 2 x 2 points");
  if (!std::isfinite(waterLevel))
    throw std::invalid_argument("HeightField: the water level is not finite");
  cellsX_ = map_->width - 1;
  cellsZ_ = map_->depth - 1;
  const uint16_t top = *std::max_element(map_->values.begin(), map_->values.end());
  if (!(top * kRaw > water_))
    throw std::invalid_argument("HeightField: the water level is at or above the highest point");
  // The floor lies POV-Ray's HFIELD_OFFSET (0.001 of a 16-bit step) below the water, as
  // its bounding box does: the surface at the water level itself is kept, a face of the
  // solid, as POV-Ray shows it.
  floor_ = water_ - 0.001 * kRaw;
  bounds_ = AABB(Vec3(0.0, floor_, 0.0), Vec3(1.0, top * kRaw, 1.0));

  // Level 0: each cell's corners; level L + 1: the 2 x 2 blocks of level L.
  std::vector<MinMax> cells(static_cast<size_t>(cellsX_) * cellsZ_);
  for (int j = 0; j < cellsZ_; ++j)
    for (int i = 0; i < cellsX_; ++i) {
      const uint16_t a = map_->at(i, j), b = map_->at(i + 1, j), c = map_->at(i, j + 1),
                     d = map_->at(i + 1, j + 1);
      cells[static_cast<size_t>(j) * cellsX_ + i] = {std::min({a, b, c, d}),
                                                     std::max({a, b, c, d})};
    }
  levels_.push_back(std::move(cells));
  levelWidth_.push_back(cellsX_);
  int w = cellsX_, h = cellsZ_;
  while (w > 1 || h > 1) {
    const int nw = (w + 1) / 2, nh = (h + 1) / 2;
    const std::vector<MinMax>& below = levels_.back();
    std::vector<MinMax> next(static_cast<size_t>(nw) * nh, MinMax{65535, 0});
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        MinMax& m = next[static_cast<size_t>(j / 2) * nw + i / 2];
        const MinMax& s = below[static_cast<size_t>(j) * w + i];
        m.lo = std::min(m.lo, s.lo);
        m.hi = std::max(m.hi, s.hi);
      }
    levels_.push_back(std::move(next));
    levelWidth_.push_back(nw);
    w = nw;
    h = nh;
  }

  if (smooth_) {
    // POV-Ray's vertex normals, quantised to shorts as it stores them, then taken to object
    // space (its transform's normal matrix scales x by W - 1, y by 65536, z by H - 1).
    vertexNormals_.resize(map_->values.size());
    for (int z = 0; z <= cellsZ_; ++z)
      for (int x = 0; x <= cellsX_; ++x) {
        Vec3 n(0.0);
        int k = 0;
        k += addFaceNormal(*map_, x, z, x + 1, z, x, z + 1, n);
        k += addFaceNormal(*map_, x, z, x, z + 1, x - 1, z, n);
        k += addFaceNormal(*map_, x, z, x - 1, z, x, z - 1, n);
        k += addFaceNormal(*map_, x, z, x, z - 1, x + 1, z, n);
        const double len = glm::length(n);
        n = (k > 0 && len > 1e-10) ? n / len : Vec3(0.0, 1.0, 0.0);
        const Vec3 q(static_cast<short>(32767 * n.x), static_cast<short>(32767 * n.y),
                     static_cast<short>(32767 * n.z));
        Vec3 o(q.x * cellsX_, q.y * 65536.0, q.z * cellsZ_);
        const double ol = glm::length(o);
        vertexNormals_[static_cast<size_t>(z) * map_->width + x] =
            ol > 0.0 ? o / ol : Vec3(0.0, 1.0, 0.0);
      }
  }
}

size_t HeightField::triangleCount() const { return 2 * static_cast<size_t>(cellsX_) * cellsZ_; }

double HeightField::triangleHeightGrid(int i, int j, bool upper, double X, double Z) const {
  if (!upper) {
    const double y1 = gridHeight(i, j), y2 = gridHeight(i + 1, j), y3 = gridHeight(i, j + 1);
    return y1 + (y2 - y1) * (X - i) + (y3 - y1) * (Z - j);
  }
  const double y4 = gridHeight(i + 1, j + 1), y3 = gridHeight(i, j + 1), y2 = gridHeight(i + 1, j);
  return y4 + (y3 - y4) * (i + 1 - X) + (y2 - y4) * (j + 1 - Z);
}

double HeightField::height(double x, double z) const {
  const double X = x * cellsX_, Z = z * cellsZ_;
  const int i = std::clamp(static_cast<int>(std::floor(X)), 0, cellsX_ - 1);
  const int j = std::clamp(static_cast<int>(std::floor(Z)), 0, cellsZ_ - 1);
  return triangleHeightGrid(i, j, (X - i) + (Z - j) > 1.0, X, Z);
}

bool HeightField::inside(const Vec3& p) const {
  if (open_) return false;  // a surface has no inside
  if (!(p.x >= 0.0 && p.x <= 1.0 && p.z >= 0.0 && p.z <= 1.0)) return false;
  if (p.y < floor_) return false;
  return p.y < height(p.x, p.z);
}

template <class Sink>
void HeightField::walk(const Ray& ray, Sink&& sink) const {
  // Grid space: x and z in cells, y as in object space; t is unchanged.
  const Vec3 O(ray.o.x * cellsX_, ray.o.y, ray.o.z * cellsZ_);
  const Vec3 D(ray.d.x * cellsX_, ray.d.y, ray.d.z * cellsZ_);
  const Vec3 lo(0.0, bounds_.lo.y, 0.0), hi(cellsX_, bounds_.hi.y, cellsZ_);
  static constexpr uint32_t kLowFace[3] = {kWallX0, kFloor, kWallZ0};
  static constexpr uint32_t kHighFace[3] = {kWallX1, kTop, kWallZ1};
  double t0 = -kInf, t1 = kInf;
  uint32_t face0 = kTop, face1 = kTop;
  for (int a = 0; a < 3; ++a) {
    if (D[a] == 0.0) {
      if (O[a] < lo[a] || O[a] > hi[a]) return;
      continue;
    }
    double ta = (lo[a] - O[a]) / D[a], tb = (hi[a] - O[a]) / D[a];
    uint32_t fa = kLowFace[a], fb = kHighFace[a];
    if (D[a] < 0.0) {
      std::swap(ta, tb);
      std::swap(fa, fb);
    }
    if (ta > t0) t0 = ta, face0 = fa;
    if (tb < t1) t1 = tb, face1 = fb;
  }
  if (!(t0 <= t1)) return;

  auto cellOf = [](double p, double d, int cells) {
    int c = static_cast<int>(std::floor(p));
    if (d < 0.0 && p == c) --c;
    return std::clamp(c, 0, cells - 1);
  };
  auto nextX = [&](int i) {
    return D.x > 0.0 ? (i + 1 - O.x) / D.x : D.x < 0.0 ? (i - O.x) / D.x : kInf;
  };
  auto nextZ = [&](int j) {
    return D.z > 0.0 ? (j + 1 - O.z) / D.z : D.z < 0.0 ? (j - O.z) / D.z : kInf;
  };
  auto triPart = [&](int i, int j, bool upper) {
    return 2u * (static_cast<uint32_t>(j) * static_cast<uint32_t>(cellsX_) +
                 static_cast<uint32_t>(i)) +
           (upper ? 1u : 0u);
  };

  // The box's top lies at the highest grid point, so where the field is flat at that
  // height the top is the surface itself: a crossing there is the triangle's (an open
  // field draws no top face, and would lose it).
  auto faceOrSurface = [&](uint32_t face, double at) {
    if (face != kTop) return face;
    const double X = std::clamp(O.x + at * D.x, 0.0, hi.x),
                 Z = std::clamp(O.z + at * D.z, 0.0, hi.z);
    const int ci = cellOf(X, D.x, cellsX_), cj = cellOf(Z, D.z, cellsZ_);
    return triPart(ci, cj, (X - ci) + (Z - cj) > 1.0);
  };

  double t = t0;
  int i = cellOf(std::clamp(O.x + t * D.x, 0.0, hi.x), D.x, cellsX_);
  int j = cellOf(std::clamp(O.z + t * D.z, 0.0, hi.z), D.z, cellsZ_);
  bool neg;  // is the ray below the surface at t?
  {
    const double X = O.x + t * D.x, Z = O.z + t * D.z;
    const bool upper = (X - i) + (Z - j) > 1.0;
    neg = O.y + t * D.y - triangleHeightGrid(i, j, upper, X, Z) < 0.0;
    if (neg && sink(t0, faceOrSurface(face0, t0), true)) return;
  }
  double tx = nextX(i), tz = nextZ(j);
  const int top = static_cast<int>(levels_.size()) - 1;
  int level = top;
  while (true) {
    // The largest block around the cell the ray passes wholly above or below.
    bool skipped = false;
    for (; level >= 0; --level) {
      const int bi = i >> level, bj = j >> level;
      const MinMax& mm = levels_[level][static_cast<size_t>(bj) * levelWidth_[level] + bi];
      const int xs = bi << level, xe = std::min((bi + 1) << level, cellsX_);
      const int zs = bj << level, ze = std::min((bj + 1) << level, cellsZ_);
      const double txe = D.x > 0.0 ? (xe - O.x) / D.x : D.x < 0.0 ? (xs - O.x) / D.x : kInf;
      const double tze = D.z > 0.0 ? (ze - O.z) / D.z : D.z < 0.0 ? (zs - O.z) / D.z : kInf;
      const double te = std::min({txe, tze, t1});
      const double ya = O.y + t * D.y, yb = O.y + te * D.y;
      const double margin = 1e-10 * (1.0 + std::abs(ya) + std::abs(yb));
      const bool above = std::min(ya, yb) > mm.hi * kRaw + margin;
      const bool below = std::max(ya, yb) < mm.lo * kRaw - margin;
      if (!above && !below) continue;
      if (below != neg) {  // rounding disagrees with the bounds: cross where they meet
        neg = below;
        const double X = O.x + t * D.x, Z = O.z + t * D.z;
        if (sink(t, triPart(i, j, (X - i) + (Z - j) > 1.0), neg)) return;
      }
      t = te;
      skipped = true;
      if (te >= t1) break;
      if (txe < tze) {
        i = D.x > 0.0 ? xe : xs - 1;
        j = std::clamp(cellOf(O.z + t * D.z, D.z, cellsZ_), zs, ze - 1);
      } else if (tze < txe) {
        j = D.z > 0.0 ? ze : zs - 1;
        i = std::clamp(cellOf(O.x + t * D.x, D.x, cellsX_), xs, xe - 1);
      } else {
        i = D.x > 0.0 ? xe : xs - 1;
        j = D.z > 0.0 ? ze : zs - 1;
      }
      break;
    }
    if (skipped) {
      if (t >= t1 || i < 0 || i >= cellsX_ || j < 0 || j >= cellsZ_) break;
      tx = nextX(i);
      tz = nextZ(j);
      level = std::min(level + 1, top);
      continue;
    }
    // One cell: up to two pieces, split where the ray crosses the diagonal.
    const double tc = std::min({tx, tz, t1});
    double ends[3] = {t, tc, tc};
    int pieces = 1;
    const double sd = D.x + D.z;
    if (sd != 0.0) {
      const double td = (i + j + 1 - O.x - O.z) / sd;
      if (td > t && td < tc) {
        ends[1] = td;
        pieces = 2;
      }
    }
    for (int k = 0; k < pieces; ++k) {
      const double ta = ends[k], tb = ends[k + 1];
      const double tm = 0.5 * (ta + tb);
      const bool upper = (O.x - i) + (O.z - j) + tm * sd > 1.0;
      // The ray's height above the piece's triangle, A + B t.
      double A, B;
      if (!upper) {
        const double y1 = gridHeight(i, j), y2 = gridHeight(i + 1, j), y3 = gridHeight(i, j + 1);
        A = O.y - y1 - (y2 - y1) * (O.x - i) - (y3 - y1) * (O.z - j);
        B = D.y - (y2 - y1) * D.x - (y3 - y1) * D.z;
      } else {
        const double y4 = gridHeight(i + 1, j + 1), y3 = gridHeight(i, j + 1),
                     y2 = gridHeight(i + 1, j);
        A = O.y - y4 - (y3 - y4) * (i + 1 - O.x) - (y2 - y4) * (j + 1 - O.z);
        B = D.y + (y3 - y4) * D.x + (y2 - y4) * D.z;
      }
      const bool negB = A + B * tb < 0.0;
      if (negB != neg) {
        double tr = B != 0.0 ? -A / B : ta;
        tr = std::clamp(tr, ta, tb);
        neg = negB;
        if (sink(tr, triPart(i, j, upper), neg)) return;
      }
    }
    t = tc;
    if (tc >= t1) break;
    const bool stepX = tx <= tz, stepZ = tz <= tx;
    if (stepX) i += D.x > 0.0 ? 1 : -1;
    if (stepZ) j += D.z > 0.0 ? 1 : -1;
    if (i < 0 || i >= cellsX_ || j < 0 || j >= cellsZ_) break;
    if (stepX) tx = nextX(i);
    if (stepZ) tz = nextZ(j);
    level = std::min(1, top);
  }
  if (neg) sink(t1, faceOrSurface(face1, t1), false);
}

bool HeightField::intersect(const Ray& ray, Hit& hit) const {
  bool found = false;
  walk(ray, [&](double t, uint32_t part, bool) {
    if (open_ && part >= kWallX0) return false;  // no walls, no floor
    if (t <= ray.tmin) return false;
    if (t < ray.tmax) {
      hit.t = t;
      hit.shape = this;
      hit.part = part;
      found = true;
    }
    return true;
  });
  return found;
}

void HeightField::crossings(const Ray& ray, CrossingList& out) const {
  bool inside = false;
  walk(ray, [&](double t, uint32_t part, bool entering) {
    if (open_ && part >= kWallX0) return false;  // no walls, no floor
    if (t < ray.tmin) {
      inside = entering && !open_;
      return false;
    }
    if (t > ray.tmax) return true;
    Crossing c;
    c.hit.t = t;
    c.hit.shape = this;
    c.hit.part = part;
    c.entering = entering || open_;  // a surface's crossings all enter
    out.items.push_back(c);
    return false;
  });
  out.startsInside = inside;
}

Vec3 HeightField::flatNormal(int i, int j, bool upper) const {
  Vec3 n;
  if (!upper)
    n = Vec3((gridHeight(i, j) - gridHeight(i + 1, j)) * cellsX_, 1.0,
             (gridHeight(i, j) - gridHeight(i, j + 1)) * cellsZ_);
  else
    n = Vec3((gridHeight(i, j + 1) - gridHeight(i + 1, j + 1)) * cellsX_, 1.0,
             (gridHeight(i + 1, j) - gridHeight(i + 1, j + 1)) * cellsZ_);
  return glm::normalize(n);
}

// POV-Ray's bilinear blend of the cell's four vertex normals (hfield.cpp, Normal).
template <class Map>
Vec3 HeightField::blendNormals(double X, double Z, Map&& toWorld) const {
  const int px = std::clamp(static_cast<int>(X), 0, cellsX_ - 1),
            pz = std::clamp(static_cast<int>(Z), 0, cellsZ_ - 1);
  const double x = X - px, z = Z - pz, u = 1.0 - x, v = 1.0 - z;
  auto n = [&](int a, int b) {
    return toWorld(vertexNormals_[static_cast<size_t>(b) * map_->width + a]);
  };
  const Vec3 r =
      v * (u * n(px, pz) + x * n(px + 1, pz)) + z * (u * n(px, pz + 1) + x * n(px + 1, pz + 1));
  const double len = glm::length(r);
  return len > 0.0 ? r / len : Vec3(0.0, 1.0, 0.0);
}

Vec3 HeightField::smoothNormal(double X, double Z) const {
  return blendNormals(X, Z, [](const Vec3& n) { return n; });
}

bool HeightField::worldShadingNormal(const Ray& objectRay, const Hit& hit,
                                     const Transform& worldFromObject, Vec3& ns) const {
  if (!smooth_ || hit.part >= kWallX0) return false;
  const Vec3 p = objectRay.at(hit.t);
  const Vec3 s = blendNormals(p.x * cellsX_, p.z * cellsZ_,
                              [&](const Vec3& n) { return worldFromObject.normalToWorld(n); });
  const uint32_t cell = hit.part >> 1;
  const Vec3 ng = worldFromObject.normalToWorld(
      flatNormal(static_cast<int>(cell % static_cast<uint32_t>(cellsX_)),
                 static_cast<int>(cell / static_cast<uint32_t>(cellsX_)), (hit.part & 1u) != 0));
  ns = glm::dot(s, ng) > 0.0 ? s : ng;  // never behind the facet, as surface() keeps it
  return true;
}

SurfaceInfo HeightField::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo si;
  si.p = ray.at(hit.t);
  Vec3 n;
  switch (hit.part) {
    case kWallX0:
      n = Vec3(-1.0, 0.0, 0.0);
      break;
    case kWallX1:
      n = Vec3(1.0, 0.0, 0.0);
      break;
    case kWallZ0:
      n = Vec3(0.0, 0.0, -1.0);
      break;
    case kWallZ1:
      n = Vec3(0.0, 0.0, 1.0);
      break;
    case kFloor:
      n = Vec3(0.0, -1.0, 0.0);
      break;
    default: {
      const uint32_t cell = hit.part >> 1;
      const int i = static_cast<int>(cell % static_cast<uint32_t>(cellsX_));
      const int j = static_cast<int>(cell / static_cast<uint32_t>(cellsX_));
      n = flatNormal(i, j, (hit.part & 1u) != 0);
      si.ng = n;
      si.ns = n;
      if (smooth_) {
        const Vec3 s = smoothNormal(si.p.x * cellsX_, si.p.z * cellsZ_);
        if (glm::dot(s, n) > 0.0) si.ns = s;  // never behind the facet
      }
      si.pError = gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + Vec3(1.0));
      return si;
    }
  }
  si.ng = n;
  si.ns = n;
  si.pError = gamma(32) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d) + Vec3(1.0));
  return si;
}

}  // namespace lucent
