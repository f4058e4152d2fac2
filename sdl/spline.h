// POV-Ray's `spline { }` values: a parameter and a vector (2 to 5 components) per entry,
// interpolated as POV-Ray 3.7 interpolates them (its splines.cpp, read for the facts), so
// that a scene moving a camera or objects along a spline puts them where POV-Ray does.
//   linear_spline (the default): straight lines between the entries;
//   quadratic_spline: the parabola through each entry's neighbours;
//   cubic_spline: Catmull-Rom, through the second to the next-to-last entry;
//   natural_spline: the natural cubic spline (second derivative 0 at both ends).
// Before the first parameter and after the last the value is held (the first or last
// entry; cubic_spline holds the second and the next-to-last).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace lucent::sdl {

// The most entries one spline holds (docs/povray-import.md, "Limits").
constexpr size_t kMaxSplineEntries = 1'000'000;

enum class SplineKind { Linear, Quadratic, Cubic, Natural };

struct Spline {
  struct Entry {
    double par = 0;
    std::array<double, 5> v{};
  };
  SplineKind kind = SplineKind::Linear;
  std::vector<Entry> entries;  // by increasing parameter
  int terms = 2;               // the most components any entry was given (2 to 5)
  // natural_spline's second derivatives at the entries, per component (finish()).
  std::array<std::vector<double>, 5> curvature;

  // Once every entry is in: what natural_spline needs (computed for every spline, as a call
  // may ask for any kind).
  void finish();

  // The value at `t` (`terms` components of the result are meaningful), as `kind`
  // interpolates.
  std::array<double, 5> at(double t, SplineKind kind) const;
  std::array<double, 5> at(double t) const { return at(t, kind); }
};

// Component `member` (0 to 4, or 5 for POV-Ray's grey of the first three) of the spline's
// value at the parameter whose expression text is `t` (an atom or parenthesised), written as
// a Lucent expression (docs/scene-language.md, "Expressions"): conditions on t choosing
// each segment's polynomial (spline_text.cpp), for isosurfaces and function patterns.
std::string splineText(const Spline& s, const std::string& t, int member);

// The entries of a `spline { }` as they are read, in any order. An entry at a parameter
// already present replaces that one's vector, except at the highest parameter of two or
// more entries, where POV-Ray 3.7 keeps the old vector (its insertion writes past the last
// entry).
class SplineEntries {
 public:
  SplineEntries() = default;
  explicit SplineEntries(const Spline& from);  // `spline { Other ... }`
  void insert(double par, const std::array<double, 5>& v);
  size_t size() const { return byPar_.size(); }
  // The spline, its entries by increasing parameter, finished.
  Spline make(SplineKind kind, int terms) const;

 private:
  std::map<double, std::array<double, 5>> byPar_;
};

}  // namespace lucent::sdl
