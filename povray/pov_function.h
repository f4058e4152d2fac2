// An expression of the scene language (contract, "Expressions") written as a POV-Ray
// function body. POV-Ray's functions have neither '^' nor '?:' nor '!' nor a floored '%',
// and name some functions differently, so the expression is parsed (by the contract's
// precedence) and written back, fully parenthesised, with POV-Ray's operators and
// functions: a ^ b as pow(a, b), c ? a : b as select(-abs(c), a, b), and so on. Its names
// other than x, y and z (u and v in a parametric's) are written as the numbers they stood for.
#pragma once

#include "scenegraph/pigment_function.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lucent {

// The POV-Ray text, or nullopt with `problem` set for what POV-Ray cannot express
// (random()). `number` writes a number in POV-Ray's syntax. A call of one of `pigments` is
// written as a call of its declaration (povPigmentFunctionName) with its member (`.red`).
std::optional<std::string> povFunctionText(
    const std::string& text, const std::vector<std::pair<std::string, double>>& constants,
    const std::function<std::string(double)>& number, std::string& problem,
    const std::vector<std::shared_ptr<const PigmentFunction>>& pigments = {});

// The identifier a pigment function is declared as (`#declare NAME = function { pigment { } }`,
// pov_patterns.h writePigmentFunctions).
std::string povPigmentFunctionName(const PigmentFunction& f);

}  // namespace lucent
