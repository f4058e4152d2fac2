// A spline function's component as Lucent expression text (spline.h, splineText): the
// pieces of Spline::at written out, each segment's polynomial behind a bisection of
// conditions on the parameter, so that a call in an isosurface or a function pattern is
// the value POV-Ray's spline gives (its ends held as Spline::at holds them).
#include "function.h"
#include "spline.h"

#include "lang/expression.h"

namespace lucent::sdl {

namespace {

std::string paren(const std::string& s) { return "(" + s + ")"; }

// A number as an atom (a negative one parenthesised).
std::string num(double v) {
  const std::string s = formatNumber(v);
  return s[0] == '-' ? paren(s) : s;
}

class SplineWriter {
 public:
  SplineWriter(const Spline& s, const std::string& t, int k) : s_(s), e_(s.entries), t_(t), k_(k) {}

  // Spline::at's cases, by the segment index i it finds (segmentEnd): 0 at or before the
  // first parameter, the number of entries after the last.
  std::string text() const {
    const size_t last = e_.size() - 1;
    auto v = [&](size_t i) { return num(e_[i].v[k_]); };
    if (last == 0) return v(0);
    switch (s_.kind) {
      case SplineKind::Linear:
      case SplineKind::Natural:
      case SplineKind::Quadratic:
        if (s_.kind == SplineKind::Quadratic && last == 1) return ends(v(0), linear(0), v(1));
        return ends(v(0), segments(1, last), v(last));
      case SplineKind::Cubic:
        if (last == 1) return num((e_[0].v[k_] + e_[1].v[k_]) / 2.0);
        // At or before entry 1: its value; past entry last-1: that one's.
        if (last == 2) return v(1);
        return paren(t_ + " <= " + num(e_[1].par) + " ? " + v(1) + " : " +
                     paren(t_ + " > " + num(e_[last - 1].par) + " ? " + v(last - 1) + " : " +
                           segments(2, last - 1)));
    }
    return "0";
  }

 private:
  // v0 at or before the first parameter, vn at or after the last, `inside` between.
  std::string ends(const std::string& v0, const std::string& inside, const std::string& vn) const {
    return paren(t_ + " <= " + num(e_.front().par) + " ? " + v0 + " : " +
                 paren(t_ + " >= " + num(e_.back().par) + " ? " + vn + " : " + inside));
  }

  // Segments i = from..to (each the piece Spline::at takes for parameters in
  // (par[i-1], par[i]]), split in halves by conditions.
  std::string segments(size_t from, size_t to) const {
    if (from == to) return piece(from);
    const size_t mid = (from + to) / 2;
    return paren(t_ + " <= " + num(e_[mid].par) + " ? " + segments(from, mid) + " : " +
                 segments(mid + 1, to));
  }

  std::string piece(size_t i) const {
    switch (s_.kind) {
      case SplineKind::Linear:
        return linear(i - 1);
      case SplineKind::Quadratic:
        return quadratic(i > 1 ? i - 1 : i);
      case SplineKind::Natural:
        return natural(i - 1);
      case SplineKind::Cubic:
        return catmullRom(i - 1);
    }
    return "0";
  }

  std::string d(size_t i) const { return paren(t_ + " - " + num(e_[i].par)); }

  std::string linear(size_t i) const {
    const double p1 = e_[i].par, p2 = e_[i + 1].par, v1 = e_[i].v[k_], v2 = e_[i + 1].v[k_];
    return paren(d(i) + "*" + num((v2 - v1) / (p2 - p1)) + " + " + num(v1));
  }

  // The parabola through entries i-1, i and i+1, as (a p + b) p + c (spline.cpp's).
  std::string quadratic(size_t i) const {
    const double p1 = e_[i - 1].par, p2 = e_[i].par, p3 = e_[i + 1].par;
    const double v1 = e_[i - 1].v[k_], v2 = e_[i].v[k_], v3 = e_[i + 1].v[k_];
    const double n = (p2 - p1) * (p3 - p1) * (p3 - p2);
    const double a = (-p2 * v1 + p3 * v1 + p1 * v2 - p3 * v2 - p1 * v3 + p2 * v3) / n;
    const double b =
        (p2 * p2 * v1 - p3 * p3 * v1 - p1 * p1 * v2 + p3 * p3 * v2 + p1 * p1 * v3 - p2 * p2 * v3) /
        n;
    const double c = (-p2 * p2 * p3 * v1 + p2 * p3 * p3 * v1 + p1 * p1 * p3 * v2 -
                      p1 * p3 * p3 * v2 - p1 * p1 * p2 * v3 + p1 * p2 * p2 * v3) /
                     n;
    return paren(paren(num(a) + "*" + t_ + " + " + num(b)) + "*" + t_ + " + " + num(c));
  }

  // The natural spline's cubic on segment i, in powers of t - par[i] (spline.cpp's order).
  std::string natural(size_t i) const {
    const std::vector<double>& m = s_.curvature[static_cast<size_t>(k_)];
    const double h = e_[i + 1].par - e_[i].par;
    const double c1 = -(h / 6.0) * (m[i + 1] + 2.0 * m[i]) + (e_[i + 1].v[k_] - e_[i].v[k_]) / h;
    const std::string inner =
        paren(num(m[i] / 2.0) + " + " + d(i) + "*" + num((m[i + 1] - m[i]) / (6.0 * h)));
    return paren(num(e_[i].v[k_]) + " + " + d(i) + "*" +
                 paren(num(c1) + " + " + d(i) + "*" + inner));
  }

  // Catmull-Rom on segment i in powers of u = (t - par[i]) / (par[i+1] - par[i]).
  std::string catmullRom(size_t i) const {
    const double dt = e_[i + 1].par - e_[i].par;
    const double v0 = e_[i].v[k_], v1 = e_[i + 1].v[k_];
    const double slope = (v1 - v0) / dt;
    const double dp0 = ((v0 - e_[i - 1].v[k_]) / (e_[i].par - e_[i - 1].par) + slope) / 2.0 * dt;
    const double dp1 =
        ((e_[i + 2].v[k_] - v1) / (e_[i + 2].par - e_[i + 1].par) + slope) / 2.0 * dt;
    const std::string u = paren(d(i) + "/" + num(dt));
    const double c2 = -3 * v0 + 3 * v1 - 2 * dp0 - dp1, c3 = 2 * v0 - 2 * v1 + dp0 + dp1;
    return paren(num(v0) + " + " + u + "*" +
                 paren(num(dp0) + " + " + u + "*" + paren(num(c2) + " + " + u + "*" + num(c3))));
  }

  const Spline& s_;
  const std::vector<Spline::Entry>& e_;
  const std::string& t_;
  int k_;
};

}  // namespace

std::string splineText(const Spline& s, const std::string& t, int member) {
  if (s.entries.empty()) return "0";
  if (member == kMemberHf)  // .hf: the first two, POV-Ray's MegaPOV height
    return paren("(" + SplineWriter(s, t, 0).text() + " + " + SplineWriter(s, t, 1).text() +
                 " / 255) * " + formatNumber(kHfScale));
  if (member == kMemberGray)  // .gray: POV-Ray's weights of the first three
    return paren("0.297*" + SplineWriter(s, t, 0).text() + " + 0.589*" +
                 SplineWriter(s, t, 1).text() + " + 0.114*" + SplineWriter(s, t, 2).text());
  return SplineWriter(s, t, member).text();
}

}  // namespace lucent::sdl
