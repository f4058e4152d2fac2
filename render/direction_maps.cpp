#include "direction_maps.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace lucent {

namespace {

// sign() that never returns 0: a direction on an octant boundary must fold to one side.
double signNotZero(double a) { return a >= 0.0 ? 1.0 : -1.0; }

}  // namespace

// ---- Octahedral ------------------------------------------------------------------------

Vec3 octahedralDirection(const Vec2& uv) {
  // p in [-1,1]^2 with +y up (uv's v grows downwards).
  double px = 2.0 * uv.x - 1.0, py = 1.0 - 2.0 * uv.y;
  double z = 1.0 - std::abs(px) - std::abs(py);
  double x = px, y = py;
  if (z < 0.0) {  // a corner triangle: unfold onto the back half of the octahedron
    x = (1.0 - std::abs(py)) * signNotZero(px);
    y = (1.0 - std::abs(px)) * signNotZero(py);
  }
  return glm::normalize(Vec3(x, y, z));
}

Vec2 octahedralUV(const Vec3& d) {
  double l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  double px = d.x / l1, py = d.y / l1;
  if (d.z < 0.0) {  // back half: fold into the corners
    double fx = (1.0 - std::abs(py)) * signNotZero(px);
    double fy = (1.0 - std::abs(px)) * signNotZero(py);
    px = fx;
    py = fy;
  }
  return Vec2(0.5 * (px + 1.0), 0.5 * (1.0 - py));
}

// ---- Cube map --------------------------------------------------------------------------

CubeFaceAxes cubeFaceAxes(CubeFace face) {
  // Local coordinates (x right, y up, z forward) are left-handed, so each face's right is
  // -(forward x up) here; written out to keep the table readable.
  switch (face) {
    case CubeFace::Right:
      return {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    case CubeFace::Left:
      return {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
    case CubeFace::Up:
      return {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
    case CubeFace::Down:
      return {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}};
    case CubeFace::Back:
      return {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}};
    case CubeFace::Front:
      break;
  }
  return {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
}

namespace {

struct Cell {
  CubeFace face;
  int col, row;
};

const std::array<Cell, 6>& cells(CubemapLayout layout) {
  static const std::array<Cell, 6> cross{{{CubeFace::Up, 1, 0},
                                          {CubeFace::Left, 0, 1},
                                          {CubeFace::Front, 1, 1},
                                          {CubeFace::Right, 2, 1},
                                          {CubeFace::Back, 3, 1},
                                          {CubeFace::Down, 1, 2}}};
  static const std::array<Cell, 6> strip{{{CubeFace::Right, 0, 0},
                                          {CubeFace::Left, 1, 0},
                                          {CubeFace::Up, 2, 0},
                                          {CubeFace::Down, 3, 0},
                                          {CubeFace::Back, 4, 0},
                                          {CubeFace::Front, 5, 0}}};
  return layout == CubemapLayout::Cross ? cross : strip;
}

}  // namespace

int cubeLayoutColumns(CubemapLayout layout) { return layout == CubemapLayout::Cross ? 4 : 6; }
int cubeLayoutRows(CubemapLayout layout) { return layout == CubemapLayout::Cross ? 3 : 1; }

bool cubeFaceAt(CubemapLayout layout, int col, int row, CubeFace& face) {
  for (const Cell& c : cells(layout))
    if (c.col == col && c.row == row) {
      face = c.face;
      return true;
    }
  return false;
}

void cubeFaceCell(CubemapLayout layout, CubeFace face, int& col, int& row) {
  for (const Cell& c : cells(layout))
    if (c.face == face) {
      col = c.col;
      row = c.row;
      return;
    }
}

CubeFace cubeFaceOf(const Vec3& d) {
  double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  if (ax >= ay && ax >= az) return d.x > 0.0 ? CubeFace::Right : CubeFace::Left;
  if (ay >= az) return d.y > 0.0 ? CubeFace::Up : CubeFace::Down;
  return d.z > 0.0 ? CubeFace::Front : CubeFace::Back;
}

CubeFacePoint cubeFacePoint(const Vec3& d) {
  CubeFace face = cubeFaceOf(d);
  CubeFaceAxes axes = cubeFaceAxes(face);
  // Central projection onto the face plane at distance 1: a, b in [-1, 1].
  double m = glm::dot(d, axes.forward);
  double a = std::clamp(glm::dot(d, axes.right) / m, -1.0, 1.0);
  double b = std::clamp(glm::dot(d, axes.up) / m, -1.0, 1.0);
  return {face, Vec2(0.5 * (a + 1.0), 0.5 * (1.0 - b))};
}

bool cubemapDirection(CubemapLayout layout, const Vec2& uv, Vec3& direction) {
  const int cols = cubeLayoutColumns(layout), rows = cubeLayoutRows(layout);
  double x = uv.x * cols, y = uv.y * rows;
  // The right and bottom image edges belong to the last cell.
  int col = std::clamp(static_cast<int>(std::floor(x)), 0, cols - 1);
  int row = std::clamp(static_cast<int>(std::floor(y)), 0, rows - 1);
  CubeFace face;
  if (!cubeFaceAt(layout, col, row, face)) return false;
  double a = 2.0 * (x - col) - 1.0, b = 1.0 - 2.0 * (y - row);
  CubeFaceAxes axes = cubeFaceAxes(face);
  direction = glm::normalize(axes.forward + a * axes.right + b * axes.up);
  return true;
}

Vec2 cubemapUV(CubemapLayout layout, const Vec3& direction) {
  CubeFacePoint p = cubeFacePoint(direction);
  int col = 0, row = 0;
  cubeFaceCell(layout, p.face, col, row);
  return Vec2((col + p.st.x) / cubeLayoutColumns(layout), (row + p.st.y) / cubeLayoutRows(layout));
}

// ---- Fibonacci sphere ------------------------------------------------------------------

namespace {

// The golden ratio's conjugate (sqrt(5) - 1) / 2 = 1 / phi: successive points turn by the
// golden angle 2 pi (1 - 1/phi), the most irrational rotation (Vogel 1979).
constexpr double kGoldenConjugate = 0.61803398874989484820;

double fibonacciHeight(uint64_t k, uint64_t n) {
  return 1.0 - (2.0 * static_cast<double>(k) + 1.0) / static_cast<double>(n);
}

}  // namespace

Vec3 fibonacciDirection(uint64_t k, uint64_t n) {
  double y = fibonacciHeight(k, n);
  double turns = static_cast<double>(k) * kGoldenConjugate;
  double phi = 2.0 * kPi * (turns - std::floor(turns));
  double s = std::sqrt(std::max(0.0, 1.0 - y * y));
  return Vec3(s * std::sin(phi), y, s * std::cos(phi));
}

uint64_t nearestFibonacciIndex(const Vec3& direction, uint64_t n) {
  const Vec3 d = glm::normalize(direction);
  // The (fractional) index whose height equals the direction's; its neighbours in index
  // are its neighbours in height.
  double position = (1.0 - d.y) * 0.5 * static_cast<double>(n) - 0.5;
  int64_t last = static_cast<int64_t>(n) - 1;
  // Scan two ways from there: prev walks to smaller indices, next to larger ones.
  int64_t prev = std::clamp(static_cast<int64_t>(std::floor(position)), int64_t{0}, last);
  int64_t next = prev + 1;

  double best = kInf;
  uint64_t bestIndex = static_cast<uint64_t>(prev);
  auto consider = [&](int64_t k) {
    Vec3 q = fibonacciDirection(static_cast<uint64_t>(k), n);
    Vec3 diff = q - d;
    double dist2 = glm::dot(diff, diff);
    if (dist2 < best || (dist2 == best && static_cast<uint64_t>(k) < bestIndex)) {
      best = dist2;
      bestIndex = static_cast<uint64_t>(k);
    }
  };
  // |q - d|^2 >= (q.y - d.y)^2: once the height gap alone exceeds the best squared
  // distance on both sides, no further point can be nearer.
  auto gap2 = [&](int64_t k) {
    double g = fibonacciHeight(static_cast<uint64_t>(k), n) - d.y;
    return g * g;
  };
  while (true) {
    bool canPrev = prev >= 0 && gap2(prev) <= best;
    bool canNext = next <= last && gap2(next) <= best;
    if (!canPrev && !canNext) break;
    if (canPrev && (!canNext || gap2(prev) <= gap2(next))) consider(prev--);
    else consider(next++);
  }
  return bestIndex;
}

}  // namespace lucent
