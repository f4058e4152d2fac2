// POV-Ray's internal functions, `internal(N)` as functions.inc declares them
// (`#declare f_sphere = function { internal(61) }`): each one's name and number of
// parameters (x, y, z and its own), and, for the closed forms Lucent evaluates, the formula
// twice: as C++ for a call in an expression and as Lucent expression text for an isosurface
// (the tests hold the two to the same values). The formulas are those of POV-Ray 3.7's
// fnintern.cpp, read for the facts.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// internal(76), f_noise3d: POV-Ray's noise at the point (a pattern function of bozo).
inline constexpr int kNoise3d = 76;

struct InternalFunction {
  const char* name;  // as functions.inc declares it
  int params;        // x, y, z and its own
  // The closed form; null when Lucent does not evaluate it (then `refusal` says why).
  double (*evaluate)(const double* p);
  // The same formula as Lucent expression text, $0..$9 standing for the parameters (or,
  // for the clamped polynomials, the words X, Y, Z, X2, Y2, Z2 for the point and its
  // squares, P0, P1... for the function's own parameters).
  const char* text;
};

// The internal function N, or null when POV-Ray 3.7 has none.
const InternalFunction* internalFunction(int n);

// Why internal function N cannot be evaluated (it has no closed form here).
std::string internalRefusal(int n);

// The internal function named `name` (f_sphere...), or null.
const InternalFunction* internalFunctionNamed(std::string_view name);

// The internal functions Lucent evaluates in closed form, in POV-Ray's order: the
// functions of the expression language by these names (docs/scene-language.md).
const std::vector<const InternalFunction*>& evaluatedInternalFunctions();

// The function's formula as Lucent expression text, its $0..$9 and the words X, Y, Z, X2,
// Y2, Z2, P0..P9 replaced by the argument texts (each parenthesised by the caller).
std::string internalFormula(const InternalFunction& f, const std::vector<std::string>& args);

}  // namespace lucent
