// POV-Ray 3.7's noise, written from its description in texture.cpp: a lattice noise whose
// corners carry linear functions (coefficients from a 267-entry table, chosen by a hashed
// permutation) for generators 1 and 2, and Perlin's gradient noise for generator 3. The
// random tables come from POV-Ray's linear congruential generator, so they are rebuilt here
// from the same seeds rather than stored; the coefficient table is data and is copied.
#include "noise.h"

#include <cmath>
#include <cstdint>

namespace lucent {

namespace {

constexpr double kEpsilon = 1.0e-10;              // POV-Ray's EPSILON
constexpr int kLatticeOffset = 10000;             // POV-Ray's -MINX: keeps lattice indices positive
constexpr int kSolidEntries = 2048;               // generator 3's table size (a power of two)
constexpr double kRollover = 10000000.023157213;  // generator 3's offset of every coordinate

// POV-Ray's random coefficients (texture.cpp, RTable): 267 values; POV-Ray interleaves
// each with half of itself, which the table below does when it is built.
constexpr double kCoefficients[267] = {
    -1,        0.604974,  -0.937102,  0.414115,  0.576226,   -0.0161593, 0.432334,    0.103685,
    0.590539,  0.0286412, 0.46981,    -0.84622,  -0.0734112, -0.304097,  -0.40206,    -0.210132,
    -0.919127, 0.652033,  -0.83151,   -0.183948, -0.671107,  0.852476,   0.043595,    -0.404532,
    0.75494,   -0.335653, 0.618433,   0.605707,  0.708583,   -0.477195,  0.899474,    0.490623,
    0.221729,  -0.400381, -0.853727,  -0.932586, 0.659113,   0.961303,   0.325948,    -0.750851,
    0.842466,  0.734401,  -0.649866,  0.394491,  -0.466056,  -0.434073,  0.109026,    0.0847028,
    -0.738857, 0.241505,  0.16228,    -0.71426,  -0.883665,  -0.150408,  -0.90396,    -0.686549,
    -0.785214, 0.488548,  0.0246433,  0.142473,  -0.602136,  0.375845,   -0.00779736, 0.498955,
    -0.268147, 0.856382,  -0.386007,  -0.596094, -0.867735,  -0.570977,  -0.914366,   0.28896,
    0.672206,  -0.233783, 0.94815,    0.895262,  0.343252,   -0.173388,  -0.767971,   -0.314748,
    0.824308,  -0.342092, 0.721431,   -0.24004,  -0.63653,   0.553277,   0.376272,    0.158984,
    -0.452659, 0.396323,  -0.420676,  -0.454154, 0.122179,   0.295857,   0.0664225,   -0.202075,
    -0.724788, 0.453513,  0.224567,   -0.908812, 0.176349,   -0.320516,  -0.697139,   0.742702,
    -0.900786, 0.471489,  -0.133532,  0.119127,  -0.889769,  -0.23183,   -0.669673,   -0.046891,
    -0.803433, -0.966735, 0.475578,   -0.652644, 0.0112459,  -0.730007,  0.128283,    0.145647,
    -0.619318, 0.272023,  0.392966,   0.646418,  -0.0207675, -0.315908,  0.480797,    0.535668,
    -0.250172, -0.83093,  -0.653773,  -0.443809, 0.119982,   -0.897642,  0.89453,     0.165789,
    0.633875,  -0.886839, 0.930877,   -0.537194, 0.587732,   0.722011,   -0.209461,   -0.0424659,
    -0.814267, -0.919432, 0.280262,   -0.66302,  -0.558099,  -0.537469,  -0.598779,   0.929656,
    -0.170794, -0.537163, 0.312581,   0.959442,  0.722652,   0.499931,   0.175616,    -0.534874,
    -0.685115, 0.444999,  0.17171,    0.108202,  -0.768704,  -0.463828,  0.254231,    0.546014,
    0.869474,  0.875212,  -0.944427,  0.130724,  -0.110185,  0.312184,   -0.33138,    -0.629206,
    0.0606546, 0.722866,  -0.0979477, 0.821561,  0.0931258,  -0.972808,  0.0318151,   -0.867033,
    -0.387228, 0.280995,  -0.218189,  -0.539178, -0.427359,  -0.602075,  0.311971,    0.277974,
    0.773159,  0.592493,  -0.0331884, -0.630854, -0.269947,  0.339132,   0.581079,    0.209461,
    -0.317433, -0.284993, 0.181323,   0.341634,  0.804959,   -0.229572,  -0.758907,   -0.336721,
    0.605463,  -0.991272, -0.0188754, -0.300191, 0.368307,   -0.176135,  -0.3832,     -0.749569,
    0.62356,   -0.573938, 0.278309,   -0.971313, 0.839994,   -0.830686,  0.439078,    0.66128,
    0.694514,  0.0565042, 0.54342,    -0.438804, -0.0228428, -0.687068,  0.857267,    0.301991,
    -0.494255, -0.941039, 0.775509,   0.410575,  -0.362081,  -0.671534,  -0.348379,   0.932433,
    0.886442,  0.868681,  -0.225666,  -0.062211, -0.0976425, -0.641444,  -0.848112,   0.724697,
    0.473503,  0.998749,  0.174701,   0.559625,  -0.029099,  -0.337392,  -0.958129,   -0.659785,
    0.236042,  -0.246937, 0.659449,   -0.027512, 0.821897,   -0.226215,  0.0181735,   0.500481,
    -0.420127, -0.427878, 0.566186,
};

// POV-Ray's generator: next = next * 1812433253 + 12345 in 32 bits, 15 bits taken from the
// high half. Unsigned arithmetic gives the bits POV-Ray's int arithmetic gives on x86-64.
struct PovRandom {
  uint32_t state;
  int next() {
    state = state * 1812433253u + 12345u;
    return static_cast<int>((state >> 16) & 0x7FFFu);
  }
};

struct NoiseTables {
  uint16_t hash[8192];
  double coeff[267 * 2];
  int permutation[2 * (kSolidEntries + 1)];
  double gradient[2 * (kSolidEntries + 1)][3];

  NoiseTables() : hash{}, coeff{}, permutation{}, gradient{} {
    // The hash: a shuffle of 0..4095 (InitTextureTable), repeated so two lookups can be
    // chained with an xor without a mask.
    for (int i = 0; i < 4096; ++i) hash[i] = static_cast<uint16_t>(i);
    PovRandom lattice{0};
    for (int i = 4095; i >= 0; --i) {
      int j = lattice.next() % 4096;
      uint16_t t = hash[i];
      hash[i] = hash[j];
      hash[j] = t;
    }
    for (int i = 0; i < 4096; ++i) hash[4096 + i] = hash[i];

    for (int i = 0; i < 267; ++i) {
      coeff[2 * i] = kCoefficients[i];
      coeff[2 * i + 1] = kCoefficients[i] * 0.5;
    }

    // Generator 3 (InitSolidNoise): unit gradients by rejection, then a permutation made
    // by POV-Ray's swap loop (every second entry), both repeated past the end.
    PovRandom solid{1};
    for (int i = 0; i < kSolidEntries; ++i) {
      double v[3];
      double s;
      do {
        for (double& c : v)
          c = static_cast<double>(solid.next() % (kSolidEntries << 1) - kSolidEntries) /
              static_cast<double>(kSolidEntries);
        s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
      } while (s > 1.0 || s < 1.0e-5);
      s = 1.0 / std::sqrt(s);
      for (int k = 0; k < 3; ++k) gradient[i][k] = v[k] * s;
    }
    for (int i = 0; i < kSolidEntries; ++i) permutation[i] = i;
    for (int i = kSolidEntries; i > 0; i -= 2) {
      int k = permutation[i];
      int j = solid.next() % kSolidEntries;
      permutation[i] = permutation[j];
      permutation[j] = k;
    }
    for (int i = 0; i < kSolidEntries + 2; ++i) {
      permutation[kSolidEntries + i] = permutation[i];
      for (int k = 0; k < 3; ++k) gradient[kSolidEntries + i][k] = gradient[i][k];
    }
  }
};

const NoiseTables& tables() {
  static const NoiseTables t;
  return t;
}

// Coordinates this large have no fractional digits left; POV-Ray's int conversion would
// overflow there (undefined behaviour), so they are brought back into range first.
double tame(double x) {
  if (std::fabs(x) < 2.0e9) return x;
  return std::isfinite(x) ? std::fmod(x, 4096.0) : 0.0;
}

// POV-Ray's lattice cell of x ("JB fix"): truncation for x >= 0, and below zero a
// truncation of x - (1 - EPSILON), so points within 1e-10 above an integer round up.
int latticeBelow(double x) {
  return x >= 0.0 ? static_cast<int>(x) : static_cast<int>(x - (1.0 - kEpsilon));
}

struct Lattice {
  int ix, iy, iz;                             // cell indices, masked to 0..4095
  double x_ix, y_iy, z_iz, x_jx, y_jy, z_jz;  // offsets from the cell's two corners
  double sx, sy, sz, tx, ty, tz;              // smoothstep weights and their complements
};

double scurve(double a) { return a * a * (3.0 - 2.0 * a); }

Lattice lattice(const Vec3& p) {
  Lattice l;
  double x = tame(p.x), y = tame(p.y), z = tame(p.z);
  int t = latticeBelow(x);
  l.ix = (t + kLatticeOffset) & 0xFFF;
  l.x_ix = x - t;
  t = latticeBelow(y);
  l.iy = (t + kLatticeOffset) & 0xFFF;
  l.y_iy = y - t;
  t = latticeBelow(z);
  l.iz = (t + kLatticeOffset) & 0xFFF;
  l.z_iz = z - t;
  l.x_jx = l.x_ix - 1;
  l.y_jy = l.y_iy - 1;
  l.z_jz = l.z_iz - 1;
  l.sx = scurve(l.x_ix);
  l.sy = scurve(l.y_iy);
  l.sz = scurve(l.z_iz);
  l.tx = 1 - l.sx;
  l.ty = 1 - l.sy;
  l.tz = 1 - l.sz;
  return l;
}

int hash2(const NoiseTables& t, int a, int b) { return t.hash[t.hash[a] ^ b]; }
// Index of a corner's four coefficients in coeff (POV-Ray's Hash1dRTableIndex).
int coeffIndex(const NoiseTables& t, int a, int b) { return (t.hash[a ^ b] & 0xFF) * 2; }

// One corner's weighted linear function, summed in POV-Ray's order (INCRSUMP).
double corner(const double* m, double s, double x, double y, double z) {
  return s * (m[1] + m[2] * x + m[4] * y + m[6] * z);
}

double latticeNoise(const Vec3& p) {
  const NoiseTables& t = tables();
  const Lattice l = lattice(p);
  const double txty = l.tx * l.ty, sxty = l.sx * l.ty, txsy = l.tx * l.sy, sxsy = l.sx * l.sy;
  const int ixiy = hash2(t, l.ix, l.iy);
  const int jxiy = hash2(t, l.ix + 1, l.iy);
  const int ixjy = hash2(t, l.ix, l.iy + 1);
  const int jxjy = hash2(t, l.ix + 1, l.iy + 1);
  const double* c = t.coeff;
  double sum = corner(c + coeffIndex(t, ixiy, l.iz), txty * l.tz, l.x_ix, l.y_iy, l.z_iz);
  sum += corner(c + coeffIndex(t, jxiy, l.iz), sxty * l.tz, l.x_jx, l.y_iy, l.z_iz);
  sum += corner(c + coeffIndex(t, ixjy, l.iz), txsy * l.tz, l.x_ix, l.y_jy, l.z_iz);
  sum += corner(c + coeffIndex(t, jxjy, l.iz), sxsy * l.tz, l.x_jx, l.y_jy, l.z_iz);
  sum += corner(c + coeffIndex(t, ixiy, l.iz + 1), txty * l.sz, l.x_ix, l.y_iy, l.z_jz);
  sum += corner(c + coeffIndex(t, jxiy, l.iz + 1), sxty * l.sz, l.x_jx, l.y_iy, l.z_jz);
  sum += corner(c + coeffIndex(t, ixjy, l.iz + 1), txsy * l.sz, l.x_ix, l.y_jy, l.z_jz);
  sum += corner(c + coeffIndex(t, jxjy, l.iz + 1), sxsy * l.sz, l.x_jx, l.y_jy, l.z_jz);
  return sum;
}

// Generator 3's set-up of one axis (SetupSolidNoise).
struct SolidAxis {
  int b0, b1;
  double r0, r1;
};

SolidAxis solidAxis(double coordinate) {
  double t = tame(coordinate) + kRollover;
  int it = static_cast<int>(std::floor(t));
  SolidAxis a;
  a.b0 = it & (kSolidEntries - 1);
  a.b1 = (a.b0 + 1) & (kSolidEntries - 1);
  a.r0 = t - it;
  a.r1 = a.r0 - 1.0;
  return a;
}

double lerp(double t, double a, double b) { return a + t * (b - a); }

double at(const double* g, double rx, double ry, double rz) {
  return rx * g[0] + ry * g[1] + rz * g[2];
}

double solidNoise(const Vec3& p) {
  const NoiseTables& t = tables();
  const SolidAxis x = solidAxis(p.x), y = solidAxis(p.y), z = solidAxis(p.z);
  const int i = t.permutation[x.b0];
  const int j = t.permutation[x.b1];
  const int b00 = t.permutation[i + y.b0];
  const int b10 = t.permutation[j + y.b0];
  const int b01 = t.permutation[i + y.b1];
  const int b11 = t.permutation[j + y.b1];
  const double sx = scurve(x.r0), sy = scurve(y.r0), sz = scurve(z.r0);
  const auto& g = t.gradient;

  double a = lerp(sx, at(g[b00 + z.b0], x.r0, y.r0, z.r0), at(g[b10 + z.b0], x.r1, y.r0, z.r0));
  double b = lerp(sx, at(g[b01 + z.b0], x.r0, y.r1, z.r0), at(g[b11 + z.b0], x.r1, y.r1, z.r0));
  const double c = lerp(sy, a, b);
  a = lerp(sx, at(g[b00 + z.b1], x.r0, y.r0, z.r1), at(g[b10 + z.b1], x.r1, y.r0, z.r1));
  b = lerp(sx, at(g[b01 + z.b1], x.r0, y.r1, z.r1), at(g[b11 + z.b1], x.r1, y.r1, z.r1));
  const double d = lerp(sy, a, b);
  return lerp(sz, c, d);
}

double clamp01(double v) {
  if (v < 0.0) v = 0.0;
  if (v > 1.0) v = 1.0;
  return v;
}

}  // namespace

double noise(const Vec3& p, int generator) {
  if (generator == 3) {
    // POV-Ray's correction for the bias of its tables: about 5e-4 beyond [0, 1], clamped.
    return clamp01(0.5 * (1.59 * solidNoise(p) + 0.985));
  }
  double sum = latticeNoise(p);
  if (generator == 2) {
    // POV-Ray's measured range of the raw sum, [-1.05242, 0.988997], stretched to [0, 1].
    sum += 1.05242;
    sum *= 0.48985582;
    return clamp01(sum);
  }
  return clamp01(sum + 0.5);
}

Vec3 dnoise(const Vec3& p) {
  const NoiseTables& t = tables();
  const Lattice l = lattice(p);
  const double txty = l.tx * l.ty, sxty = l.sx * l.ty, txsy = l.tx * l.sy, sxsy = l.sx * l.sy;
  const int ixiy = hash2(t, l.ix, l.iy);
  const int jxiy = hash2(t, l.ix + 1, l.iy);
  const int ixjy = hash2(t, l.ix, l.iy + 1);
  const int jxjy = hash2(t, l.ix + 1, l.iy + 1);

  // Each corner's three components use three consecutive coefficient groups; the corners
  // are visited in POV-Ray's order for DNoise, which is not Noise's.
  Vec3 r(0.0);
  auto add = [&](int h, int iz, double s, double x, double y, double z) {
    const double* m = t.coeff + coeffIndex(t, h, iz);
    r.x += corner(m, s, x, y, z);
    r.y += corner(m + 8, s, x, y, z);
    r.z += corner(m + 16, s, x, y, z);
  };
  add(ixiy, l.iz, txty * l.tz, l.x_ix, l.y_iy, l.z_iz);
  add(jxiy, l.iz, sxty * l.tz, l.x_jx, l.y_iy, l.z_iz);
  add(jxjy, l.iz, sxsy * l.tz, l.x_jx, l.y_jy, l.z_iz);
  add(ixjy, l.iz, txsy * l.tz, l.x_ix, l.y_jy, l.z_iz);
  add(ixjy, l.iz + 1, txsy * l.sz, l.x_ix, l.y_jy, l.z_jz);
  add(jxjy, l.iz + 1, sxsy * l.sz, l.x_jx, l.y_jy, l.z_jz);
  add(jxiy, l.iz + 1, sxty * l.sz, l.x_jx, l.y_iy, l.z_jz);
  add(ixiy, l.iz + 1, txty * l.sz, l.x_ix, l.y_iy, l.z_jz);
  return r;
}

int latticeHash(int x, int y, int z) {
  const uint16_t* h = tables().hash;
  return h[h[h[x & 0xFFF] ^ (y & 0xFFF)] ^ (z & 0xFFF)];
}

}  // namespace lucent
