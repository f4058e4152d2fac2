// A function's tree written as a Lucent expression (function.h, functionText), for an
// isosurface: every operand is an atom or parenthesised, so that Lucent's own precedence
// (where `^` binds above unary minus) cannot regroup it; user functions are inlined with
// their arguments' texts; the internal functions Lucent evaluates are written out by their
// formulas (internal_functions.h).
#include "function.h"

#include "scenegraph/internal_functions.h"
#include "spline.h"

#include "lang/expression.h"

#include <cctype>
#include <cmath>

namespace lucent::sdl {

namespace {

constexpr double kPi = 3.1415926535897932384626;

std::string paren(const std::string& s) { return "(" + s + ")"; }

class TextWriter {
 public:
  explicit TextWriter(std::vector<PigmentCall>* pigments) : pigments_(pigments) {}

  std::string call(const FunctionValue& f, const std::vector<std::string>& args,
                   const SourceLoc& at) {
    switch (f.kind) {
      case FunctionValue::Kind::Unsupported:
      case FunctionValue::Kind::Pigment:
      case FunctionValue::Kind::Transform:
        throw FunctionError(
            at, f.describe() + " is " + f.what +
                    ", which Lucent cannot evaluate in an isosurface or a function pattern");
      case FunctionValue::Kind::Spline:
        throw FunctionError(at, f.describe() +
                                    " is a spline function, which Lucent cannot evaluate in an "
                                    "isosurface or a function pattern");
      case FunctionValue::Kind::Internal: {
        // A call of the expression language's function of the same name (the closed form,
        // evaluated natively: docs/scene-language.md).
        const InternalFunction* in = internalFunction(f.internal);
        if (!in || !in->text || !in->evaluate) throw FunctionError(at, internalRefusal(f.internal));
        std::string call = std::string(in->name) + "(";
        for (size_t k = 0; k < args.size(); ++k) call += (k ? ", " : "") + args[k];
        return checked(call + ")", at);
      }
      case FunctionValue::Kind::Expression:
        break;
    }
    return write(*f.body, args);
  }

 private:
  // Every level is held to the bound, so a tree that shares nodes (pow(pow(a, 8), 8)...)
  // cannot grow a text without end before it is refused.
  std::string write(const FnNode& n, const std::vector<std::string>& args) {
    return checked(writeNode(n, args), n.loc);
  }

  std::string writeNode(const FnNode& n, const std::vector<std::string>& args) {
    auto a = [&](size_t i) { return write(*n.args[i], args); };
    auto binary = [&](const char* op) { return paren(a(0) + " " + op + " " + a(1)); };
    switch (n.op) {
      case FnOp::Constant: {
        if (!std::isfinite(n.value))
          throw FunctionError(n.loc, "the function holds a number that is not finite");
        const std::string s = formatNumber(n.value);
        return s[0] == '-' ? paren(s) : s;
      }
      case FnOp::Param:
        return n.index < 0 ? std::string("0") : args[static_cast<size_t>(n.index)];
      case FnOp::Local:
      case FnOp::Sum:
      case FnOp::Prod:
        throw FunctionError(n.loc, "sum() and prod() cannot be written as a Lucent expression");
      case FnOp::Neg:
        return paren("-" + a(0));
      case FnOp::Add:
        return binary("+");
      case FnOp::Sub:
        return binary("-");
      case FnOp::Mul:
        return binary("*");
      case FnOp::Div:
        return binary("/");
      case FnOp::Eq:
        return binary("==");
      case FnOp::Ne:
        return binary("!=");
      case FnOp::Lt:
        return binary("<");
      case FnOp::Le:
        return binary("<=");
      case FnOp::Gt:
        return binary(">");
      case FnOp::Ge:
        return binary(">=");
      case FnOp::And:
        return binary("&&");
      case FnOp::Or:
        return binary("||");
      case FnOp::Math:
        return checked(math(static_cast<FnMath>(n.index), a(0), n.args.size() > 1 ? a(1) : ""),
                       n.loc);
      case FnOp::Min:
      case FnOp::Max: {
        std::string s = n.op == FnOp::Min ? "min(" : "max(";
        for (size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + a(i);
        return checked(s + ")", n.loc);
      }
      case FnOp::Select: {
        const std::string c = a(0);
        if (n.args.size() == 3) return paren(c + " < 0 ? " + a(1) + " : " + a(2));
        return checked(
            paren(c + " < 0 ? " + a(1) + " : " + paren(c + " == 0 ? " + a(2) + " : " + a(3))),
            n.loc);
      }
      case FnOp::Call: {
        if (n.member >= 0 && n.callee->kind == FunctionValue::Kind::Pigment && pigments_)
          return checked(pigmentCall(n, a(0), a(1), a(2)), n.loc);
        // A spline function's component: its segments' polynomials written out.
        if (n.member >= 0 && n.callee->kind == FunctionValue::Kind::Spline)
          return checked(splineText(*n.callee->spline, a(0), n.member), n.loc);
        if (n.member >= 0)
          throw FunctionError(
              n.loc, n.callee->describe() + " is " +
                         (n.callee->what.empty() ? "a spline function" : n.callee->what) +
                         ", which Lucent cannot evaluate in an isosurface or a function pattern");
        std::vector<std::string> inner(n.args.size());
        for (size_t i = 0; i < n.args.size(); ++i) inner[i] = a(i);
        return checked(paren(call(*n.callee, inner, n.loc)), n.loc);
      }
    }
    return "0";
  }

  // POV-Ray's functions in Lucent's: the same name where Lucent has it, else a formula
  // (equal to rounding for the hyperbolic ones; exact for mod, int, div, radians, degrees).
  static std::string math(FnMath m, const std::string& x, const std::string& y) {
    switch (m) {
      case FnMath::Sinh:
        return paren("(exp(" + x + ") - exp(-" + x + "))/2");
      case FnMath::Cosh:
        return paren("(exp(" + x + ") + exp(-" + x + "))/2");
      case FnMath::Tanh:
        return paren("1 - 2/(exp(2*" + x + ") + 1)");
      case FnMath::Asinh:
        return "ln(" + x + " + sqrt(" + x + "*" + x + " + 1))";
      case FnMath::Acosh:
        return "ln(" + x + " + sqrt(" + x + "*" + x + " - 1))";
      case FnMath::Atanh:
        return paren("0.5*ln((1 + " + x + ")/(1 - " + x + "))");
      case FnMath::Radians:
        return paren(x + "*" + formatNumber(kPi / 180.0));
      case FnMath::Degrees:
        return paren(x + "*" + formatNumber(180.0 / kPi));
      case FnMath::Int:
        return "trunc(" + x + ")";
      case FnMath::Div:
        return "trunc(" + x + "/" + y + ")";
      case FnMath::Mod:  // C's fmod: the sign of x, from Lucent's floored % of magnitudes
        return paren("sign(" + x + ")*(abs(" + x + ") % abs(" + y + "))");
      case FnMath::Log:
        return "log10(" + x + ")";
      case FnMath::Atan2:
      case FnMath::Pow:
        return std::string(fnMathName(m)) + "(" + x + ", " + y + ")";
      default:
        return std::string(fnMathName(m)) + "(" + x + ")";
    }
  }

  // `name(x, y, z)`, the name listed once per pigment function and component.
  std::string pigmentCall(const FnNode& n, const std::string& x, const std::string& y,
                          const std::string& z) {
    if (n.member == kMemberHf) {  // of the red and green components
      FnNode red = n, green = n;
      red.member = 0;
      green.member = 1;
      return "((" + pigmentCall(red, x, y, z) + " + " + pigmentCall(green, x, y, z) + " / 255) * " +
             formatNumber(kHfScale) + ")";
    }
    const PigmentCall* found = nullptr;
    for (const PigmentCall& c : *pigments_)
      if (c.callee == n.callee && c.member == n.member) found = &c;
    if (!found) {
      static const char* const kMembers[] = {"red", "green", "blue", "filter", "transmit", "gray"};
      std::string base = (n.callee->name.empty() ? std::string("pigment") : n.callee->name) + "_" +
                         kMembers[n.member];
      std::string name = base;
      for (int k = 2;; ++k) {
        bool taken = false;
        for (const PigmentCall& c : *pigments_) taken = taken || c.name == name;
        if (!taken) break;
        name = base + std::to_string(k);
      }
      pigments_->push_back({name, n.callee, n.member});
      found = &pigments_->back();
    }
    return found->name + "(" + x + ", " + y + ", " + z + ")";
  }

  static std::string checked(std::string s, const SourceLoc& at) {
    if (s.size() > kMaxFunctionTextLength)
      throw FunctionError(at, "the function written out as an expression is longer than " +
                                  std::to_string(kMaxFunctionTextLength) +
                                  " characters (see docs/povray-import.md)");
    return s;
  }

  std::vector<PigmentCall>* pigments_;
};

}  // namespace

std::string functionText(const FunctionValue& f, const std::vector<std::string>& args,
                         std::vector<PigmentCall>* pigments) {
  TextWriter w(pigments);
  return w.call(f, args, f.loc);
}

}  // namespace lucent::sdl
