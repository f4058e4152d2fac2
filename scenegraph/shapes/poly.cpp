// <poly order="4" coefficients="..."/>: the solid where a polynomial of degree 2 to 35 in
// x, y and z is below 0, with POV-Ray's poly's coefficient order (primitives/poly.h).
#include "scenegraph/shape_type.h"

#include "primitives/poly.h"

#include <fmt/format.h>

namespace lucent {

namespace {

Field<PolySpec> required(Field<PolySpec> f) {
  f.info.required = true;
  return f;
}

// The coefficients of the sample surfaces, in POV-Ray's order.
std::vector<double> coefficientsOf(
    int order, std::initializer_list<std::pair<std::array<int, 3>, double>> terms) {
  std::vector<double> c;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) {
        double v = 0.0;
        for (const auto& [powers, value] : terms)
          if (powers == std::array<int, 3>{i, j, k}) v = value;
        c.push_back(v);
      }
  return c;
}

}  // namespace

template <>
ShapeEntry<PolySpec> shapeEntry<PolySpec>() {
  ShapeEntry<PolySpec> e(
      "poly", "polys",
      [](const PolySpec& s) { return std::make_shared<Poly>(s.order, s.coefficients); },
      [](const PolySpec& s, PovShapeOut& out) {
        out.open("poly");
        std::string list;
        for (size_t i = 0; i < s.coefficients.size(); ++i)
          list += (i ? ", " : "") + out.number(s.coefficients[i]);
        // sturm: POV-Ray's exact root isolation (its default solver can lose roots).
        out.line(fmt::format("{}, <{}>", s.order, list));
        out.line("sturm");
      });
  e.doc =
      "The solid where a polynomial of degree 2 to 35 in x, y and z is below 0 (solid; "
      "unbounded).";
  e.fields = {
      required(readByEntry<PolySpec>("order", AttrType::Number))
          .doc("The degree: 2 to 35 (POV-Ray's MAX_ORDER)."),
      required(readByEntry<PolySpec>("coefficients", AttrType::NumberList))
          .doc("The coefficients in POV-Ray's poly order: the terms x^i y^j z^k with i descending, "
               "then j, then k: (n+1)(n+2)(n+3)/6 numbers for order n (10, 20, 35, 56, ...).")};
  e.fields[0].info.rule = NumberRule::between(2, Poly::kMaxOrder, "a whole number from 2 to 35");
  e.finish = [](PolySpec& s, AttributeInput& in) {
    if (!in.has("order")) {
      in.error("<poly> needs the attribute 'order' (a whole number from 2 to 35)");
      return;
    }
    const double order = in.number(
        "order", 0.0, NumberRule::between(2, Poly::kMaxOrder, "a whole number from 2 to 35"));
    if (in.failed()) return;
    if (order != std::floor(order)) {
      in.attrError("order", "must be a whole number from 2 to 35");
      return;
    }
    s.order = static_cast<int>(order);
    if (!in.has("coefficients")) {
      in.error(fmt::format("<poly> needs the attribute 'coefficients' ({} numbers for order {})",
                           Poly::termCount(s.order), s.order));
      return;
    }
    auto c = in.numbers("coefficients");
    if (!c) return;
    const size_t want = static_cast<size_t>(Poly::termCount(s.order));
    if (c->size() != want) {
      in.attrError("coefficients",
                   fmt::format("order {} needs {} coefficients, not {}", s.order, want, c->size()));
      return;
    }
    bool surface = false;
    for (size_t i = 0; i + 1 < c->size(); ++i) surface |= (*c)[i] != 0.0;
    if (!surface) {
      in.attrError("coefficients",
                   "every coefficient but the constant is 0, so there is no surface");
      return;
    }
    s.coefficients = std::move(*c);
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, PolySpec>>{
        {"sphere as a poly of order 2",
         {2, coefficientsOf(2, {{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -1}})}},
        {"monkey saddle",
         {3, coefficientsOf(3, {{{3, 0, 0}, 1}, {{1, 2, 0}, -3}, {{0, 0, 1}, -1}})}},
        {"torus as a quartic",  // (x²+y²+z²+R²−r²)² − 4R²(x²+z²), R = 1, r = 0.25
         {4, coefficientsOf(4, {{{4, 0, 0}, 1},
                                {{0, 4, 0}, 1},
                                {{0, 0, 4}, 1},
                                {{2, 2, 0}, 2},
                                {{2, 0, 2}, 2},
                                {{0, 2, 2}, 2},
                                {{2, 0, 0}, 2 * 0.9375 - 4},
                                {{0, 2, 0}, 2 * 0.9375},
                                {{0, 0, 2}, 2 * 0.9375 - 4},
                                {{0, 0, 0}, 0.9375 * 0.9375}})}},
        {"quartic cylinder",
         {4, coefficientsOf(4, {{{4, 0, 0}, 1}, {{0, 0, 4}, 1}, {{0, 0, 0}, -1}})}},
        {"steiner-like quartic",
         {4, coefficientsOf(4, {{{2, 2, 0}, 1},
                                {{0, 2, 2}, 1},
                                {{2, 0, 2}, 1},
                                {{1, 1, 1}, 1},
                                {{0, 0, 0}, -0.01}})}}};
  };
  return e;
}

}  // namespace lucent
