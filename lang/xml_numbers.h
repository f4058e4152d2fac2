// The text of numbers, vectors, colours and matrices in a written scene: the shortest text
// that reads back to the same value (a double's for numbers, a float's for colour
// components, which the scene keeps as floats).
#pragma once

#include "primitives/math.h"

#include <string>

namespace lucent {

std::string xmlNumber(double v);       // shortest round-trip form: 0.1, 1e+300, -0, inf
std::string xmlVector(const Vec3& v);  // "x y z"
std::string xmlColor(const Color& c);  // "r g b", each a float's shortest form
// The matrix as the transform syntax's matrix(...) with its 12 numbers (rows of 4), or ""
// for the identity.
std::string xmlMatrix(const Mat4& m);
// Text for an attribute value between double quotes: & < > " escaped, and tab, newline and
// carriage return as character references (which XML would otherwise read as spaces).
std::string xmlEscape(const std::string& text);

}  // namespace lucent
