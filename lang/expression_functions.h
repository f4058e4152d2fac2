// The operators and functions of the scene language's expressions (contract, "Expressions"),
// registered into a muParser parser. Every callback notes a fault when its arguments are
// finite but its result is not (a division by zero, sqrt(-1), an overflow): the evaluator
// then finds which occurrence caused it (expression.cpp).
#pragma once

#include <muParser.h>

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// What went wrong in the first faulty operation of an evaluation, if any.
struct ExpressionFault {
  bool happened = false;
  std::string what;  // "division by zero", "sqrt of a negative number (-1)", ...
};

// The fault record of the current thread's evaluation; cleared by the evaluator.
ExpressionFault& currentExpressionFault();

// How a parser is set up: `Plain` for evaluation; `Locating` adds, for each operator and
// function, a twin that throws on a fault (its operator written with a character that
// expressions never hold, its name prefixed with '@'), so that replacing one occurrence by
// its twin tells whether that occurrence is the faulty one; the twin records the fault's
// message before it throws.
enum class ParserRole { Plain, Locating };
void defineLanguage(mu::Parser& parser, ParserRole role);

// The binary operators that can fault, and the character of each one's twin.
struct OperatorTwin {
  char op;
  char twin;
};
const std::vector<OperatorTwin>& faultingOperators();
constexpr char kFunctionTwinPrefix = '@';

// The contract's function names, for "did you mean" and for telling a function from a name.
const std::vector<std::string_view>& expressionFunctionNames();

// random(seed, i): a number in [0, 1) that depends only on the two arguments' values (their
// IEEE-754 bits, with -0 read as 0), through integer hashing: the same on every machine.
double sceneRandom(double seed, double i);

// a % b, floored: the result has the sign of b (-1 % 3 = 2), as the contract says.
double flooredModulo(double a, double b);

}  // namespace lucent
