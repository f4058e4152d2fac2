#include "crackle.h"

#include "primitives/noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <random>

namespace lucent {

namespace {

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr int kCubes = kCrackleCubes;

// POV-Ray's PatternRands: the first outputs of a default-seeded 32-bit Mersenne twister
// divided by 2^32 (boost's uniform_real on [0, 1)). The cell hash is below 4096 and each
// cell takes three consecutive values.
struct CellRandoms {
  std::array<double, 4096 + 2> value;
  CellRandoms() {
    std::mt19937 twister;  // default seed 5489, as boost's mt19937
    for (double& v : value) v = static_cast<double>(twister()) / 4294967296.0;
  }
};

const CellRandoms& cellRandoms() {
  static const CellRandoms r;
  return r;
}

// The 81 neighbour offsets in POV-Ray's order (InitialiseCrackleCubeTable): every cube of
// the 5×5×5 block around p's with at most one coordinate at distance 2.
struct CubeTable {
  int offset[kCubes][3];
  CubeTable() : offset{} {
    int n = 0;
    for (int x = -2; x <= 2; ++x)
      for (int y = -2; y <= 2; ++y)
        for (int z = -2; z <= 2; ++z)
          if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) <= 1) {
            offset[n][0] = x;
            offset[n][1] = y;
            offset[n][2] = z;
            ++n;
          }
  }
};

const CubeTable& cubeTable() {
  static const CubeTable t;
  return t;
}

// The cell below x, as POV-Ray's (int)floor(x - EPSILON) (cells: floor(x + EPSILON)); far
// coordinates are brought into range first (the cell grid repeats every 4096 through the
// hash).
int cellBelow(double x, double nudge = -kEpsilon) {
  double f = std::floor(x + nudge);
  if (!(std::fabs(f) < 2.0e9)) f = std::isfinite(f) ? std::fmod(f, 4096.0) : 0.0;
  return static_cast<int>(f);
}

Vec3 cellPoint(int x, int y, int z) {
  const auto& r = cellRandoms().value;
  const int seed = latticeHash(x, y, z);
  return Vec3(x + r[seed], y + r[seed + 1], z + r[seed + 2]);
}

// The 81 neighbours' points of the cube (fx, fy, fz), kept for the last cube this thread
// asked about: the points a pixel's rays, a normal's slope samples and a tile's next pixel
// ask about mostly lie in one cube, and finding its neighbours (a hash and three random
// numbers each) was a third of a crackle's time (as POV-Ray keeps a cache of them too).
const Vec3* neighbourPoints(int fx, int fy, int fz) {
  struct Cache {
    bool filled = false;
    int x = 0, y = 0, z = 0;
    Vec3 points[kCubes];
  };
  thread_local Cache cache;
  if (!cache.filled || cache.x != fx || cache.y != fy || cache.z != fz) {
    const CubeTable& cubes = cubeTable();
    for (int i = 0; i < kCubes; ++i)
      cache.points[i] =
          cellPoint(fx + cubes.offset[i][0], fy + cubes.offset[i][1], fz + cubes.offset[i][2]);
    cache.filled = true;
    cache.x = fx;
    cache.y = fy;
    cache.z = fz;
  }
  return cache.points;
}

}  // namespace

double patternRandom(int index) { return cellRandoms().value[index]; }

void crackleCubePoints(const Vec3& p, Vec3 (&points)[kCrackleCubes]) {
  const Vec3* cached = neighbourPoints(cellBelow(p.x), cellBelow(p.y), cellBelow(p.z));
  std::copy(cached, cached + kCubes, points);
}

double crackleValue(const Vec3& p, const CrackleParams& crackle, int generator) {
  const double metric = crackle.metric;
  const double offset = crackle.offset;
  const bool square = metric == 2;
  const bool unity = metric == 1;
  const Vec3* points = neighbourPoints(cellBelow(p.x), cellBelow(p.y), cellBelow(p.z));

  auto distance = [&](int i) {
    const Vec3& c = points[i];
    const Vec3 d(c.x - p.x, c.y - p.y, c.z - p.z);
    if (square) return d.x * d.x + d.y * d.y + d.z * d.z;
    if (unity) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
           std::pow(std::fabs(d.z), metric);
  };

  // The nearest three, seeded from the first three cubes exactly as POV-Ray sorts them.
  double min1 = distance(0), min2 = distance(1), min3 = distance(2);
  int nearest = 0;
  if (min2 < min1) {
    std::swap(min1, min2);
    nearest = 1;
  }
  if (min3 < min1) {
    std::swap(min1, min3);
    nearest = 2;
  }
  if (min3 < min2) std::swap(min2, min3);
  for (int i = 3; i < kCubes; ++i) {
    const double sum = distance(i);
    if (sum < min1) {
      min3 = min2;
      min2 = min1;
      min1 = sum;
      nearest = i;
    } else if (sum < min2) {
      min3 = min2;
      min2 = sum;
    } else if (sum < min3) {
      min3 = sum;
    }
  }

  if (offset != 0.0) {
    const double add = square ? offset * offset : unity ? offset : std::pow(offset, metric);
    min1 += add;
    min2 += add;
    min3 += add;
  }

  const Vec3& form = crackle.form;
  double value;
  if (crackle.solid) {
    value = noise(points[nearest], generator);
  } else if (square) {
    value = form.x * std::sqrt(min1) + form.y * std::sqrt(min2) + form.z * std::sqrt(min3);
  } else if (unity) {
    value = form.x * min1 + form.y * min2 + form.z * min3;
  } else {
    value = form.x * std::pow(min1, 1.0 / metric) + form.y * std::pow(min2, 1.0 / metric) +
            form.z * std::pow(min3, 1.0 / metric);
  }
  return std::max(std::min(value, 1.0), 0.0);
}

double cellsValue(const Vec3& p) {
  const int seed =
      latticeHash(cellBelow(p.x, kEpsilon), cellBelow(p.y, kEpsilon), cellBelow(p.z, kEpsilon));
  return std::min(cellRandoms().value[seed], 1.0);
}

}  // namespace lucent
