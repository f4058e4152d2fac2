// Evaluating a function's tree as POV-Ray 3.7's function machine does (function.h).
#include "function.h"

#include "scenegraph/internal_functions.h"
#include "spline.h"

#include <climits>
#include <cmath>

namespace lucent::sdl {

namespace {

constexpr double kPi = 3.1415926535897932384626;  // POV-Ray's M_PI

// C's (int) conversion as x86 does it (out of range and NaN give INT_MIN), as POV-Ray's
// int() and div() use it.
double toInt(double x) {
  if (!(x > -2147483649.0 && x < 2147483648.0)) return INT_MIN;
  return static_cast<int>(x);
}

// `.x` ... `.transmit` (0 to 4) or `.gray` (5) of a spline function's value.
double splineMember(const std::array<double, 5>& v, int member) {
  if (member == kMemberGray) return 0.297 * v[0] + 0.589 * v[1] + 0.114 * v[2];  // POV-Ray's
  if (member == kMemberHf) return (v[0] + v[1] / 255.0) * kHfScale;
  return v[static_cast<size_t>(member)];
}

struct Frame {
  const double* args;
  std::vector<double> locals;
};

class Evaluator {
 public:
  explicit Evaluator(const PigmentValue& pigments) : pigments_(pigments) {}

  double call(const FunctionValue& f, const double* args, const SourceLoc& at, int member = -1) {
    if ((f.kind == FunctionValue::Kind::Pigment || f.kind == FunctionValue::Kind::Transform) &&
        pigments_) {
      // A pattern function gives its pigment's red (function_parse.cpp).
      if (member < 0 && f.what == "a pattern function") member = 0;
      if (member == kMemberHf) {
        const std::optional<double> r = pigments_(f, 0, args), g = pigments_(f, 1, args);
        if (r && g) return (*r + *g / 255.0) * kHfScale;
      } else if (member >= 0) {
        if (std::optional<double> v = pigments_(f, member, args)) return *v;
      }
    }
    switch (f.kind) {
      case FunctionValue::Kind::Unsupported:
      case FunctionValue::Kind::Pigment:
      case FunctionValue::Kind::Transform:
        throw FunctionError(at, "cannot evaluate " + f.describe() + ": it is " + f.what +
                                    ", which Lucent's POV-Ray reader does not evaluate");
      case FunctionValue::Kind::Internal: {
        const InternalFunction* in = internalFunction(f.internal);
        if (!in || !in->evaluate) throw FunctionError(at, internalRefusal(f.internal));
        return in->evaluate(args);
      }
      case FunctionValue::Kind::Spline:
        return f.spline->at(args[0])[0];
      case FunctionValue::Kind::Expression:
        break;
    }
    Frame frame{args, std::vector<double>(static_cast<size_t>(f.locals), 0.0)};
    return eval(*f.body, frame);
  }

 private:
  double eval(const FnNode& n, Frame& fr) {
    if (++steps_ > kMaxFunctionSteps)
      throw FunctionError(n.loc, "the function's evaluation takes more than " +
                                     std::to_string(kMaxFunctionSteps) +
                                     " steps (the limit of one call; see docs/povray-import.md)");
    auto a = [&](size_t i) { return eval(*n.args[i], fr); };
    switch (n.op) {
      case FnOp::Constant:
        return n.value;
      case FnOp::Param:
        return n.index < 0 ? 0.0 : fr.args[n.index];
      case FnOp::Local:
        return fr.locals[static_cast<size_t>(n.index)];
      case FnOp::Neg:
        return -a(0);
      case FnOp::Add:
        return a(0) + a(1);
      case FnOp::Sub:
        return a(0) - a(1);
      case FnOp::Mul:
        return a(0) * a(1);
      case FnOp::Div:
        return a(0) / a(1);
      case FnOp::Eq:
        return a(0) == a(1) ? 1.0 : 0.0;
      case FnOp::Ne:
        return a(0) != a(1) ? 1.0 : 0.0;
      case FnOp::Lt:
        return a(0) < a(1) ? 1.0 : 0.0;
      case FnOp::Le:
        return a(0) <= a(1) ? 1.0 : 0.0;
      case FnOp::Gt:
        return a(0) > a(1) ? 1.0 : 0.0;
      case FnOp::Ge:
        return a(0) >= a(1) ? 1.0 : 0.0;
      case FnOp::And: {
        const double l = a(0), r = a(1);
        return (l != 0.0 && r != 0.0) ? 1.0 : 0.0;
      }
      case FnOp::Or: {
        const double l = a(0), r = a(1);
        return (l != 0.0 || r != 0.0) ? 1.0 : 0.0;
      }
      case FnOp::Math:
        return fnMath(static_cast<FnMath>(n.index), a(0), n.args.size() > 1 ? a(1) : 0.0);
      case FnOp::Min:
      case FnOp::Max: {
        double v = a(0);
        for (size_t i = 1; i < n.args.size(); ++i) {
          const double w = a(i);
          // The machine keeps the earlier value unless the new one is strictly beyond it.
          if (n.op == FnOp::Min ? w < v : w > v) v = w;
        }
        return v;
      }
      case FnOp::Select: {
        const double c = a(0);
        if (n.args.size() == 3) return c < 0.0 ? a(1) : a(2);
        return c < 0.0 ? a(1) : c == 0.0 ? a(2) : a(3);
      }
      case FnOp::Sum:
      case FnOp::Prod: {
        const size_t slot = static_cast<size_t>(n.index);
        double acc = n.op == FnOp::Sum ? 0.0 : 1.0;
        const double from = a(0), to = a(1);
        for (double i = from; i <= to; i += 1.0) {
          fr.locals[slot] = i;
          const double v = a(2);
          acc = n.op == FnOp::Sum ? acc + v : acc * v;
        }
        return acc;
      }
      case FnOp::Call: {
        std::vector<double> args(n.args.size());
        for (size_t i = 0; i < n.args.size(); ++i) args[i] = a(i);
        if (n.callee->kind == FunctionValue::Kind::Spline && n.member >= 0)
          return splineMember(n.callee->spline->at(args[0]), n.member);
        return call(*n.callee, args.data(), n.loc, n.member);
      }
    }
    return 0.0;
  }

  const PigmentValue& pigments_;
  long long steps_ = 0;
};

}  // namespace

double fnMath(FnMath m, double x, double y) {
  switch (m) {
    case FnMath::Sin:
      return std::sin(x);
    case FnMath::Cos:
      return std::cos(x);
    case FnMath::Tan:
      return std::tan(x);
    case FnMath::Asin:
      return std::asin(x);
    case FnMath::Acos:
      return std::acos(x);
    case FnMath::Atan:
      return std::atan(x);
    case FnMath::Sinh:
      return std::sinh(x);
    case FnMath::Cosh:
      return std::cosh(x);
    case FnMath::Tanh:
      return std::tanh(x);
    case FnMath::Asinh:
      return std::asinh(x);
    case FnMath::Acosh:
      return std::acosh(x);
    case FnMath::Atanh:
      return std::atanh(x);
    case FnMath::Abs:
      return std::fabs(x);
    case FnMath::Radians:
      return x * (kPi / 180.0);  // the machine multiplies by the constant
    case FnMath::Degrees:
      return x * (180.0 / kPi);
    case FnMath::Floor:
      return std::floor(x);
    case FnMath::Int:
      return toInt(x);
    case FnMath::Ceil:
      return std::ceil(x);
    case FnMath::Sqrt:
      return std::sqrt(x);
    case FnMath::Exp:
      return std::exp(x);
    case FnMath::Ln:
      return std::log(x);
    case FnMath::Log:
      return std::log10(x);
    case FnMath::Atan2:
      return std::atan2(x, y);
    case FnMath::Pow:
      return std::pow(x, y);
    case FnMath::Mod:
      return std::fmod(x, y);
    case FnMath::Div:
      return toInt(x / y);
  }
  return 0.0;
}

const char* fnMathName(FnMath m) {
  static const char* const kNames[] = {
      "sin",   "cos",   "tan",   "asin", "acos",    "atan",    "sinh",  "cosh", "tanh",
      "asinh", "acosh", "atanh", "abs",  "radians", "degrees", "floor", "int",  "ceil",
      "sqrt",  "exp",   "ln",    "log",  "atan2",   "pow",     "mod",   "div"};
  return kNames[static_cast<int>(m)];
}

int fnMathArity(FnMath m) { return m >= FnMath::Atan2 ? 2 : 1; }

std::string FunctionValue::describe() const {
  return name.empty() ? std::string("the function") : "'" + name + "'";
}

double evaluateFunction(const FunctionValue& f, const std::vector<double>& args,
                        const PigmentValue& pigments, int member) {
  Evaluator e(pigments);
  return e.call(f, args.data(), f.loc, member);
}

}  // namespace lucent::sdl
