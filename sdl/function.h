// POV-Ray's user-defined functions (`#declare f = function(a, b) { a*x + b }`), as values of
// the language core: the body is parsed once, when the function is declared, into a small
// expression tree (declared floats, `pi` and `clock` folded in as numbers, other functions'
// calls kept as calls), which is then evaluated where a scene calls the function
// (`f(1, 2)` in an expression) and written as Lucent expression text for an isosurface
// (function_text.cpp). POV-Ray 3.7's function language, from its reference and its parser
// (read for the facts): numbers, the parameters, `+ - * /`, unary `-`, the comparisons
// `< <= = != >= >` (one level), `&` (above) `|`, the built-in functions of FnMath,
// `select`, `sum`, `prod`, calls of declared functions, and `internal(N)` as a whole body.
// POV-Ray 3.7 has no `^`, `?:` or `!` in functions.
#pragma once

#include "item_reader.h"

#include "scenegraph/source_loc.h"

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucent::sdl {

struct FunctionValue;
struct Spline;  // spline.h

enum class FnOp {
  Constant,
  Param,  // index: the argument's position; -1 for x, y or z when no parameter has the name
  Local,  // the running variable of a sum() or prod() (index: its slot)
  Neg,
  Add,
  Sub,
  Mul,
  Div,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  And,
  Or,
  Math,  // a built-in function (index: FnMath)
  Min,   // two or more arguments
  Max,
  Select,  // 3 or 4 arguments
  Sum,     // sum(i, from, to, expr): index the slot of i; args from, to, expr
  Prod,
  Call,  // a declared function: callee
};

// The built-in functions of POV-Ray 3.7's function language, one or two arguments.
enum class FnMath {
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sinh,
  Cosh,
  Tanh,
  Asinh,
  Acosh,
  Atanh,
  Abs,
  Radians,
  Degrees,
  Floor,
  Int,
  Ceil,
  Sqrt,
  Exp,
  Ln,
  Log,
  Atan2,  // the two-argument ones from here on
  Pow,
  Mod,
  Div,
};
const char* fnMathName(FnMath m);
int fnMathArity(FnMath m);
// The function's value as POV-Ray's function machine computes it (`y` for two arguments).
double fnMath(FnMath m, double x, double y);

struct FnNode;
using FnNodePtr = std::shared_ptr<const FnNode>;

struct FnNode {
  FnOp op = FnOp::Constant;
  double value = 0;  // Constant
  int index = 0;     // Param, Local, Math (an FnMath), Sum and Prod (the slot)
  std::vector<FnNodePtr> args;
  std::shared_ptr<const FunctionValue> callee;  // Call
  int member = -1;  // Call of a vector function: the component taken (`.x`, `.red`...)
  SourceLoc loc;    // where it is written (for calls: the function's name)
  // The longest chain of nodes and of calls within calls from here down (the tree may share
  // a node, as pow(a, 4) = (a*a)*(a*a) does, so this is kept, not walked).
  int depth = 1;
};

struct FunctionValue {
  enum class Kind {
    Expression,   // a body in the function language
    Internal,     // `internal(N)`: one of POV-Ray's built-in functions (internal_functions.h)
    Unsupported,  // a pigment or pattern function no reader made: refused where called
    Spline,       // `function { spline { } }`: one parameter, a vector value (`spline`)
    Pigment,      // `function { pigment { } }`: x, y, z; a colour (`pigment`, the reader's item)
    Transform,    // `function { transform { } }`: x, y, z; the point moved (`pigment`: the item)
  };
  Kind kind = Kind::Expression;
  std::string name;  // the identifier it was declared as ("" when anonymous)
  SourceLoc loc;     // where `function` is written
  std::vector<std::string> params;
  FnNodePtr body;  // Expression
  int internal = -1;
  std::string what;                      // Unsupported: "a pigment function"...
  std::shared_ptr<const Spline> spline;  // Spline
  ItemPtr pigment;  // Pigment, Transform: the scene reader's pigment or transform item
  int locals = 0;   // slots of sum() and prod() variables
  int depth = 1;    // the longest chain of nodes and calls within calls (bounded)

  int arity() const { return static_cast<int>(params.size()); }
  // "'f'" or "the function" (anonymous), for messages.
  std::string describe() const;
};

// A problem found while evaluating a function or writing it as text: `at` is the place in
// the function's text (or its declaration) that causes it.
struct FunctionError : std::runtime_error {
  FunctionError(SourceLoc where, const std::string& message)
      : std::runtime_error(message), at(std::move(where)) {}
  SourceLoc at;
};

// The bounds on functions (docs/povray-import.md, "Limits").
constexpr int kMaxFunctionDepth = 1000;  // nodes and calls within calls
// The components a function call takes after '.': 0 to 4 (`.x`/`.red` ... `.transmit`),
// `.gray` and MegaPOV's `.hf`, which POV-Ray 3.7 still takes: (red + green/255) scaled by
// 0.996093, a height field's 16-bit height from two 8-bit channels.
constexpr int kMemberGray = 5;
constexpr int kMemberHf = 6;
constexpr double kHfScale = 0.996093;

constexpr long long kMaxFunctionSteps = 10'000'000;   // nodes evaluated by one call
constexpr size_t kMaxFunctionTextLength = 1'000'000;  // characters of an isosurface's text

// f(args): POV-Ray's value of the call, as its function machine computes it (IEEE results
// for a division by zero or a logarithm of a negative number, as in POV-Ray 3.7). Throws
// FunctionError for what Lucent cannot evaluate (a pigment function, a noise function) and
// past kMaxFunctionSteps. `args` has f.arity() numbers; `member` (0 to 6, as FnNode's) is
// the component taken of a pigment or spline function's value.
// The value of a pigment or pattern function's call (its component `member` at the point
// xyz), given by the scene reader, which holds the pigment; empty when it cannot.
using PigmentValue =
    std::function<std::optional<double>(const FunctionValue& f, int member, const double* xyz)>;

double evaluateFunction(const FunctionValue& f, const std::vector<double>& args,
                        const PigmentValue& pigments = {}, int member = -1);

// f's body as a Lucent expression (docs/scene-language.md, "Expressions") in which f's
// parameters are the texts `args` (each an atom or parenthesised); user functions are
// inlined, internal functions written out by their formulas. Throws FunctionError for
// what Lucent's expressions cannot say (a noise function, sum()...) or past
// kMaxFunctionTextLength.
// A pigment function's call kept in the text as `name(x, y, z)` (functionText): the
// function called and the component its call takes (`member`: 0 red ... 5 gray).
struct PigmentCall {
  std::string name;
  std::shared_ptr<const FunctionValue> callee;
  int member = 0;
};

// `pigments`, when given, lets calls of pigment functions stay in the text, each written as
// a call of a name listed there (a pigment function with each of its components once); when
// null they are refused.
std::string functionText(const FunctionValue& f, const std::vector<std::string>& args,
                         std::vector<PigmentCall>* pigments = nullptr);

}  // namespace lucent::sdl
