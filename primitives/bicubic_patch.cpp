#include "bicubic_patch.h"

#include <cmath>
#include <stdexcept>

namespace lucent {

namespace {

// POV-Ray's tolerances: corners closer than kCorner are one point; a cross product whose
// squared length is below kNormal times those of its factors is no direction.
constexpr double kCorner = 1e-10;
constexpr double kNormal = 1e-10;

// The cubic Bernstein polynomials at t and their derivatives.
void bernstein(double t, double b[4], double db[4]) {
  const double s = 1.0 - t;
  b[0] = s * s * s;
  b[1] = 3.0 * t * s * s;
  b[2] = 3.0 * t * t * s;
  b[3] = t * t * t;
  db[0] = -3.0 * s * s;
  db[1] = 3.0 * s * s - 6.0 * t * s;
  db[2] = 6.0 * t * s - 3.0 * t * t;
  db[3] = 3.0 * t * t;
}

// A direction of `n` when it is not lost against the lengths of its factors a x b.
bool unitCross(const Vec3& a, const Vec3& b, Vec3& n) {
  n = glm::cross(a, b);
  const double len2 = glm::dot(n, n);
  if (!(len2 > kNormal * glm::dot(a, a) * glm::dot(b, b))) return false;
  n /= std::sqrt(len2);
  return true;
}

Vec3 mid(const Vec3& a, const Vec3& b) { return 0.5 * (a + b); }

// De Casteljau at 1/2 of the curve a[0], a[s], a[2s], a[3s] of `p` (stride s from `at`):
// the first half into `lo`, the second into `hi`, at the same places.
void halve(const PatchPoints& p, int at, int s, PatchPoints& lo, PatchPoints& hi) {
  const Vec3 a = p[at], b = p[at + s], c = p[at + 2 * s], d = p[at + 3 * s];
  const Vec3 ab = mid(a, b), bc = mid(b, c), cd = mid(c, d);
  const Vec3 abc = mid(ab, bc), bcd = mid(bc, cd);
  const Vec3 m = mid(abc, bcd);
  lo[at] = a, lo[at + s] = ab, lo[at + 2 * s] = abc, lo[at + 3 * s] = m;
  hi[at] = m, hi[at + s] = bcd, hi[at + 2 * s] = cd, hi[at + 3 * s] = d;
}

// The two halves of the patch at u = 1/2 (the curves along i) or at v = 1/2 (along j).
void splitU(const PatchPoints& p, PatchPoints& lo, PatchPoints& hi) {
  for (int j = 0; j < 4; ++j) halve(p, j, 4, lo, hi);
}
void splitV(const PatchPoints& p, PatchPoints& lo, PatchPoints& hi) {
  for (int i = 0; i < 4; ++i) halve(p, 4 * i, 1, lo, hi);
}

struct Builder {
  const PatchPoints& whole;
  double flatness;
  int uSteps, vSteps;
  const Mat4& frame;  // where flatness is measured
  bool framed;        // frame is not the identity
  MeshData& mesh;

  void vertex(const Vec3& p, double u, double v) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(bezierPatchNormal(whole, u, v));
    mesh.uvs.emplace_back(v, u);  // POV-Ray's texture (u, v) is the patch's (v, u)
  }

  // A part's corners P00 (u0, v0), P03 (u0, v1), P33 (u1, v1), P30 (u1, v0) as the
  // triangles (P00, P03, P33) and (P00, P33, P30).
  void leaf(const PatchPoints& p, double u0, double u1, double v0, double v1) {
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    vertex(p[0], u0, v0);
    vertex(p[3], u0, v1);
    vertex(p[15], u1, v1);
    vertex(p[12], u1, v0);
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangles.push_back({first, first + 2, first + 3});
  }

  void build(const PatchPoints& p, double u0, double u1, double v0, double v1, int depth) {
    double f = 0.0;
    if (framed) {
      PatchPoints q{};
      for (size_t k = 0; k < 16; ++k) q[k] = Vec3(frame * Vec4(p[k], 1.0));
      f = patchFlatness(q);
    } else {
      f = patchFlatness(p);
    }
    const bool flat = f >= 0.0 && f < flatness;
    const bool cutU = depth < uSteps, cutV = depth < vSteps;
    if (flat || (!cutU && !cutV)) return leaf(p, u0, u1, v0, v1);
    const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
    PatchPoints lo{}, hi{};
    if (!cutU) {
      splitV(p, lo, hi);
      build(lo, u0, u1, v0, vm, depth + 1);
      build(hi, u0, u1, vm, v1, depth + 1);
      return;
    }
    splitU(p, lo, hi);
    if (!cutV) {
      build(lo, u0, um, v0, v1, depth + 1);
      build(hi, um, u1, v0, v1, depth + 1);
      return;
    }
    PatchPoints a{}, b{};
    splitV(lo, a, b);
    build(a, u0, um, v0, vm, depth + 1);
    build(b, u0, um, vm, v1, depth + 1);
    splitV(hi, a, b);
    build(a, um, u1, v0, vm, depth + 1);
    build(b, um, u1, vm, v1, depth + 1);
  }
};

std::shared_ptr<const MeshData> checkedMesh(const PatchPoints& p, double flatness, int uSteps,
                                            int vSteps, const Mat4& frame) {
  if (uSteps < 0 || vSteps < 0 || uSteps > BicubicPatch::kMaxSteps ||
      vSteps > BicubicPatch::kMaxSteps)
    throw std::invalid_argument("bicubic-patch: u-steps and v-steps must be from 0 to 10");
  for (const Vec3& q : p)
    if (!isFinite(q)) throw std::invalid_argument("bicubic-patch: a control point is not finite");
  return bicubicPatchMesh(p, flatness, uSteps, vSteps, frame);
}

}  // namespace

Vec3 bezierPatchPoint(const PatchPoints& p, double u, double v) {
  double bu[4], dbu[4], bv[4], dbv[4];
  bernstein(u, bu, dbu);
  bernstein(v, bv, dbv);
  Vec3 s(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s += bu[i] * bv[j] * p[static_cast<size_t>(4 * i + j)];
  return s;
}

Vec3 bezierPatchNormal(const PatchPoints& p, double u, double v) {
  double bu[4], dbu[4], bv[4], dbv[4];
  bernstein(u, bu, dbu);
  bernstein(v, bv, dbv);
  Vec3 su(0.0), sv(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Vec3& q = p[static_cast<size_t>(4 * i + j)];
      su += dbu[i] * bv[j] * q;
      sv += bu[i] * dbv[j] * q;
    }
  Vec3 n;
  return unitCross(su, sv, n) ? n : Vec3(1.0, 0.0, 0.0);
}

double patchFlatness(const PatchPoints& p) {
  // Three corners that make a plane, as POV-Ray picks them: P00, P03 and P30, or P00, P33
  // and P30 when P03 is P00.
  const Vec3 a = p[0];
  Vec3 b = p[3];
  if (glm::length(a - b) < kCorner) {
    b = p[15];
    if (glm::length(a - b) < kCorner) return -1.0;
  }
  const Vec3 c = p[12];
  if (glm::length(b - c) < kCorner) return -1.0;
  Vec3 n;
  if (!unitCross(a - b, c - b, n)) return -1.0;
  double most = 0.0;
  for (const Vec3& q : p) most = std::max(most, std::abs(glm::dot(n, q - a)));
  return most;
}

std::shared_ptr<const MeshData> bicubicPatchMesh(const PatchPoints& p, double flatness, int uSteps,
                                                 int vSteps, const Mat4& flatnessFrame) {
  auto mesh = std::make_shared<MeshData>();
  const bool framed = flatnessFrame != Mat4(1.0);
  Builder{p, flatness, uSteps, vSteps, flatnessFrame, framed, *mesh}.build(p, 0.0, 1.0, 0.0, 1.0,
                                                                           0);
  return mesh;
}

Vec2 patchTextureUV(const PatchUvCorners& c, const Vec2& p) {
  // POV-Ray's order: along the first coordinate on the edges 0-1 and 3-2, then between them.
  const Vec2 low = c[0] + p.x * (c[1] - c[0]);
  const Vec2 high = c[3] + p.x * (c[2] - c[3]);
  return low + p.y * (high - low);
}

BicubicPatch::BicubicPatch(const PatchPoints& p, double flatness, int uSteps, int vSteps,
                           const Mat4& flatnessFrame, const PatchUvCorners& uvCorners)
    : mesh_(checkedMesh(p, flatness, uSteps, vSteps, flatnessFrame), true), uvCorners_(uvCorners) {
  for (const Vec2& c : uvCorners)
    if (!std::isfinite(c.x) || !std::isfinite(c.y))
      throw std::invalid_argument("bicubic patch: a uv corner is not finite");
}

SurfaceInfo BicubicPatch::surface(const Ray& ray, const Hit& hit) const {
  SurfaceInfo s = mesh_.surface(ray, hit);
  if (s.hasUV && uvCorners_ != kPatchOwnUv) s.uv = patchTextureUV(uvCorners_, s.uv);
  return s;
}

bool BicubicPatch::intersect(const Ray& ray, Hit& hit) const {
  if (!mesh_.intersect(ray, hit)) return false;
  hit.shape = this;
  return true;
}

void BicubicPatch::crossings(const Ray& ray, CrossingList& out) const {
  const size_t before = out.items.size();
  mesh_.crossings(ray, out);
  for (size_t i = before; i < out.items.size(); ++i) out.items[i].hit.shape = this;
}

}  // namespace lucent
