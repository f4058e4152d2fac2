// `spline { }` blocks and calls of splines in expressions (spline.h), as POV-Ray 3.7's
// parser reads them (express.cpp: Parse_Spline, Parse_Spline_Call, read for the facts):
//   spline { [SPLINE_IDENTIFIER] [linear_spline | quadratic_spline | cubic_spline |
//            natural_spline]... { T [,] VECTOR [,] }... }
//   S(T) and S(T, KIND): the value at T (S's own kind, or KIND for this call).
#include "spline.h"
#include "token_stream.h"

#include <cmath>

namespace lucent::sdl {

namespace {

// The kind a word names, if it names one.
bool splineKind(const Token& t, SplineKind& kind) {
  const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
  if (w == "linear_spline") kind = SplineKind::Linear;
  else if (w == "quadratic_spline") kind = SplineKind::Quadratic;
  else if (w == "cubic_spline") kind = SplineKind::Cubic;
  else if (w == "natural_spline") kind = SplineKind::Natural;
  else return false;
  return true;
}

}  // namespace

std::shared_ptr<const Spline> TokenStream::splineBlock() {
  const Token keyword = cur_;
  expect("{");
  SplineEntries entries;
  SplineKind kind = SplineKind::Linear;
  int terms = 2;
  getToken();
  if (cur_.kind == TokenKind::Identifier && cur_.value()->type == ValueType::Spline) {
    const Spline& from = *cur_.value()->spline;
    entries = SplineEntries(from);
    kind = from.kind;
    terms = from.terms;
    getToken();
  }
  while (splineKind(cur_, kind)) getToken();
  unget_ = true;
  std::array<double, 5> carry{};
  for (;;) {
    getToken();
    unget_ = true;
    if (!startsExpression(cur_)) break;
    const double par = parseFloat();
    const Token at = cur_;
    if (!std::isfinite(par)) error(at, "a spline's parameter must be a finite number");
    parseComma();
    Express e;
    int n = 2;  // a float entry is <f, f>
    express(e, n);
    parseComma();
    if (entries.size() >= kMaxSplineEntries)
      error(at, "the spline has more than " + std::to_string(kMaxSplineEntries) +
                    " entries (the limit; see docs/povray-import.md)");
    // POV-Ray reads every entry into the same five numbers: the components an entry does
    // not give keep the previous entry's (they show in a spline whose other entries have
    // more components).
    for (int k = 0; k < n; ++k) carry[static_cast<size_t>(k)] = e.v[k];
    entries.insert(par, carry);
    terms = std::max(terms, n);
  }
  getToken();
  if (!cur_.is("}"))
    error(cur_,
          "expected an entry (a parameter and a vector) or the '}' closing the spline "
          "opened at " +
              keyword.loc().str() + ", found " + cur_.describe());
  if (entries.size() == 0) error(keyword, "a spline must have at least one entry");
  return std::make_shared<const Spline>(entries.make(kind, terms));
}

void TokenStream::splineCall(Express& e, int& terms, const Spline& s, bool kindArgument) {
  const Token at = cur_;
  if (!at.call)
    error(at, "expected a numeric expression, found " + at.describe() + " (a spline is called: '" +
                  std::string(at.text()) + "(T)')");
  expect("(");
  const double t = parseFloat();
  SplineKind kind = s.kind;
  if (kindArgument && allow(",")) {
    getToken();
    if (!splineKind(cur_, kind))
      error(cur_,
            "expected linear_spline, quadratic_spline, natural_spline or cubic_spline, "
            "found " +
                cur_.describe());
  }
  expect(")");
  const std::array<double, 5> v = s.at(t, kind);
  for (int k = 0; k < 5; ++k) e.v[k] = v[static_cast<size_t>(k)];
  terms = s.terms;  // POV-Ray: the call has the spline's size
}

}  // namespace lucent::sdl
