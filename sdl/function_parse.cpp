// `function { }` read into a FunctionValue (function.h), and calls of functions in
// expressions. POV-Ray 3.7's function language, loosest first: `|`; `&`; the comparisons
// `< <= = != >= >` (one level, left to right, no parentheses needed); `+ -`; `* /`; unary
// `-` and `+`. Names: `x`/`u`, `y`/`v` and `z` are the parameters of those names (0 when the
// function has none: POV-Ray's registers), other undeclared names the parameters, declared
// floats, `pi` and `clock` numbers taken now, declared functions calls. Constant parts are
// folded as POV-Ray folds them, and `a / c` and `pow(a, c)` are computed as POV-Ray's
// compiler writes them (a * (1/c); products for c = 2..8), so that a call gives POV-Ray's
// number to the last bit.
#include "scenegraph/internal_functions.h"
#include "token_stream.h"

#include <cmath>

namespace lucent::sdl {

namespace {

constexpr double kPi = 3.1415926535897932384626;

struct MathWord {
  Kw kw;
  FnMath math;
};
constexpr MathWord kMathWords[] = {
    {Kw::k_sin, FnMath::Sin},         {Kw::k_cos, FnMath::Cos},
    {Kw::k_tan, FnMath::Tan},         {Kw::k_asin, FnMath::Asin},
    {Kw::k_acos, FnMath::Acos},       {Kw::k_atan, FnMath::Atan},
    {Kw::k_sinh, FnMath::Sinh},       {Kw::k_cosh, FnMath::Cosh},
    {Kw::k_tanh, FnMath::Tanh},       {Kw::k_asinh, FnMath::Asinh},
    {Kw::k_acosh, FnMath::Acosh},     {Kw::k_atanh, FnMath::Atanh},
    {Kw::k_abs, FnMath::Abs},         {Kw::k_radians, FnMath::Radians},
    {Kw::k_degrees, FnMath::Degrees}, {Kw::k_floor, FnMath::Floor},
    {Kw::k_int, FnMath::Int},         {Kw::k_ceil, FnMath::Ceil},
    {Kw::k_sqrt, FnMath::Sqrt},       {Kw::k_exp, FnMath::Exp},
    {Kw::k_ln, FnMath::Ln},           {Kw::k_log, FnMath::Log},
    {Kw::k_atan2, FnMath::Atan2},     {Kw::k_pow, FnMath::Pow},
    {Kw::k_mod, FnMath::Mod},         {Kw::k_div, FnMath::Div},
};

// The deepest chain below `n`'s arguments and callee, plus `n` itself.
int depthOf(const FnNode& n) {
  int d = 0;
  for (const FnNodePtr& a : n.args) d = std::max(d, a->depth);
  if (n.callee) d += n.callee->depth;
  return d + 1;
}

FnNodePtr node(FnOp op, std::vector<FnNodePtr> args, const SourceLoc& loc) {
  auto n = std::make_shared<FnNode>();
  n->op = op;
  n->args = std::move(args);
  n->loc = loc;
  n->depth = depthOf(*n);
  return n;
}

FnNodePtr constant(double v, const SourceLoc& loc) {
  auto n = std::make_shared<FnNode>();
  n->value = v;
  n->loc = loc;
  return n;
}

bool isConstant(const FnNodePtr& n) { return n->op == FnOp::Constant; }

// A binary operation, folded when both sides are numbers (as POV-Ray folds them).
FnNodePtr binary(FnOp op, FnNodePtr l, FnNodePtr r, const SourceLoc& loc) {
  if (isConstant(l) && isConstant(r)) {
    const double a = l->value, b = r->value;
    switch (op) {
      case FnOp::Add:
        return constant(a + b, loc);
      case FnOp::Sub:
        return constant(a - b, loc);
      case FnOp::Mul:
        return constant(a * b, loc);
      case FnOp::Div:
        return constant(a / b, loc);
      case FnOp::Eq:
        return constant(a == b, loc);
      case FnOp::Ne:
        return constant(a != b, loc);
      case FnOp::Lt:
        return constant(a < b, loc);
      case FnOp::Le:
        return constant(a <= b, loc);
      case FnOp::Gt:
        return constant(a > b, loc);
      case FnOp::Ge:
        return constant(a >= b, loc);
      case FnOp::And:
        return constant(a != 0.0 && b != 0.0, loc);
      case FnOp::Or:
        return constant(a != 0.0 || b != 0.0, loc);
      default:
        break;
    }
  }
  return node(op, {std::move(l), std::move(r)}, loc);
}

// pow(x, n) for n = 2..8 as POV-Ray's compiler multiplies it out.
FnNodePtr power(const FnNodePtr& x, int n, const SourceLoc& loc) {
  auto mul = [&](FnNodePtr a, FnNodePtr b) {
    return node(FnOp::Mul, {std::move(a), std::move(b)}, loc);
  };
  const FnNodePtr x2 = mul(x, x);
  switch (n) {
    case 2:
      return x2;
    case 3:
      return mul(x2, x);
    case 4:
      return mul(x2, x2);
    case 5:
      return mul(mul(x2, x2), x);
    case 6:
      return mul(mul(x2, x2), x2);
    case 7:
      return mul(mul(mul(x2, x2), x), x2);
    default:
      return mul(mul(x2, x2), mul(x2, x2));
  }
}

int memberIndex(const Token& t) {
  switch (t.kw) {
    case Kw::k_x:
    case Kw::k_u:
    case Kw::k_red:
      return 0;
    case Kw::k_y:
    case Kw::k_v:
    case Kw::k_green:
      return 1;
    case Kw::k_z:
    case Kw::k_blue:
      return 2;
    case Kw::k_t:
    case Kw::k_filter:
      return 3;
    case Kw::k_transmit:
      return 4;
    case Kw::k_gray:
      return kMemberGray;
    default:
      if (t.text() == "grey") return kMemberGray;
      if (t.text() == "hf") return kMemberHf;
      return -1;
  }
}

}  // namespace

// What the body being read can name.
struct TokenStream::FnScope {
  FunctionValue& f;
  std::string self;  // the identifier being declared (a call of it is a recursion)
  int xReg = -1, yReg = -1, zReg = -1;
  std::vector<std::pair<std::string, int>> locals;  // sum() and prod() variables, in scope
};

std::shared_ptr<const FunctionValue> TokenStream::parseFunction(bool declaration,
                                                                const std::string& name) {
  auto f = std::make_shared<FunctionValue>();
  f->name = name;
  f->loc = cur_.loc();
  getToken();
  const bool paramList = cur_.is("(");
  if (paramList) {
    if (!declaration)
      error(cur_, "this function takes no parameter list (its parameters are x, y and z)");
    for (;;) {
      getToken();
      if (cur_.is(")") && !f->params.empty()) break;
      const bool axis = cur_.kind == TokenKind::Keyword &&
                        (cur_.kw == Kw::k_x || cur_.kw == Kw::k_y || cur_.kw == Kw::k_z ||
                         cur_.kw == Kw::k_u || cur_.kw == Kw::k_v);
      if (!axis && cur_.kind != TokenKind::Undeclared)
        error(cur_, "expected a parameter name (one not declared, or x, y, z, u, v), found " +
                        cur_.describe());
      f->params.emplace_back(cur_.text());
      parseComma();
    }
    getToken();
  }
  if (!cur_.is("{")) error(cur_, "expected '{' after 'function', found " + cur_.describe());
  const Token open = cur_;
  getToken();
  const std::string_view word = cur_.kind == TokenKind::Keyword ? cur_.text() : "";
  if (declaration && word == "internal") {
    expect("(");
    getToken();
    const Token number = cur_;
    if (number.kind != TokenKind::Number)
      error(number, "expected the internal function's number, found " + number.describe());
    const int n = static_cast<int>(number.number());
    const InternalFunction* in = internalFunction(n);
    if (!in) error(number, "function 'internal(" + std::to_string(n) + ")' does not exist");
    expect(")");
    expect("}");
    f->kind = FunctionValue::Kind::Internal;
    f->internal = n;
    f->params = {"x", "y", "z"};
    for (int i = 3; i < in->params; ++i) f->params.push_back("P" + std::to_string(i - 3));
    if (n == kNoise3d && items_) {
      // f_noise3d is the value of POV-Ray's bozo pattern (both are its Noise at the point
      // with the scene's generator): a pattern function of it.
      if ((f->pigment = items_->patternPigment(*this, true))) {
        f->kind = FunctionValue::Kind::Pigment;
        f->what = "a pattern function";
      }
    }
    return f;
  }
  if (declaration &&
      (word == "pigment" || word == "pattern" || word == "transform" || word == "spline")) {
    if (paramList)
      error(cur_, "a " + std::string(word) + " function takes no parameter list (POV-Ray's rule)");
    if (word == "spline") {
      f->kind = FunctionValue::Kind::Spline;
      f->spline = splineBlock();
      f->params = {"t"};
      expect("}");
      return f;
    }
    f->kind = FunctionValue::Kind::Unsupported;
    f->what = "a " + std::string(word) + " function";
    f->params = {"x", "y", "z"};
    if (word == "pattern" && items_) {
      // A pigment whose red is the pattern's value, evaluated as pigment functions are.
      f->pigment = items_->patternPigment(*this, false);
      if (f->pigment) f->kind = FunctionValue::Kind::Pigment;
      // A reader that makes no pigments leaves the block unread.
      if (rawPeek().kind == RawKind::Punct && rawPeek().text == "{") fnSkipBlock();
      expect("}");
      return f;
    }
    if ((word == "pigment" || word == "transform") && items_) {
      // The scene reader reads the block. A pigment function's colour is evaluated by
      // isosurfaces and function patterns; a transform function (transforms.inc's
      // vtransform calls one) moves the point (x, y, z), a vector.
      const bool pigment = word == "pigment";  // taken before `word`'s token moves on
      const Token t = cur_;
      f->pigment = items_->read(t, *this);
      if (f->pigment && f->pigment->kind() == (pigment ? "pigment" : "transform"))
        f->kind = pigment ? FunctionValue::Kind::Pigment : FunctionValue::Kind::Transform;
      expect("}");
      return f;
    }
    fnSkipBlock();
    expect("}");
    return f;
  }
  unget_ = true;
  if (f->params.empty()) f->params = {"x", "y", "z"};
  FnScope scope{*f, name, -1, -1, -1, {}};
  for (int i = 0; i < f->arity(); ++i) {
    const std::string& p = f->params[static_cast<size_t>(i)];
    if (p == "x" || p == "u") scope.xReg = i;
    if (p == "y" || p == "v") scope.yReg = i;
    if (p == "z") scope.zReg = i;
  }
  f->body = fnOr(scope);
  getToken();
  if (!cur_.is("}"))
    error(cur_, "expected an operator or the '}' closing the function opened at " +
                    open.loc().str() + ", found " + cur_.describe());
  f->depth = f->body->depth;
  if (f->depth > kMaxFunctionDepth)
    error(f->loc, "this function's operations and calls are nested more than " +
                      std::to_string(kMaxFunctionDepth) +
                      " deep (the limit; see docs/povray-import.md)");
  return f;
}

// A pigment, pattern, transform or spline block, kept by no one: read to its brace.
void TokenStream::fnSkipBlock() {
  expect("{");
  for (int depth = 1; depth > 0;) {
    getToken();
    if (cur_.kind == TokenKind::End) error(cur_, "the function's block is not closed");
    if (cur_.is("{")) ++depth;
    if (cur_.is("}")) --depth;
  }
}

FnNodePtr TokenStream::fnOr(FnScope& s) {
  Nesting nesting(*this);
  FnNodePtr l = fnAnd(s);
  for (;;) {
    getToken();
    if (!cur_.is("|")) {
      unget_ = true;
      return l;
    }
    const SourceLoc at = cur_.loc();
    l = binary(FnOp::Or, l, fnAnd(s), at);
  }
}

FnNodePtr TokenStream::fnAnd(FnScope& s) {
  FnNodePtr l = fnCompare(s);
  for (;;) {
    getToken();
    if (!cur_.is("&")) {
      unget_ = true;
      return l;
    }
    const SourceLoc at = cur_.loc();
    l = binary(FnOp::And, l, fnCompare(s), at);
  }
}

FnNodePtr TokenStream::fnCompare(FnScope& s) {
  FnNodePtr l = fnSum(s);
  for (;;) {
    getToken();
    FnOp op;
    if (cur_.is("<")) op = FnOp::Lt;
    else if (cur_.is("<=")) op = FnOp::Le;
    else if (cur_.is("=")) op = FnOp::Eq;
    else if (cur_.is("!=")) op = FnOp::Ne;
    else if (cur_.is(">=")) op = FnOp::Ge;
    else if (cur_.is(">")) op = FnOp::Gt;
    else {
      unget_ = true;
      return l;
    }
    const SourceLoc at = cur_.loc();
    l = binary(op, l, fnSum(s), at);
  }
}

FnNodePtr TokenStream::fnSum(FnScope& s) {
  FnNodePtr l = fnProduct(s);
  for (;;) {
    getToken();
    const bool add = cur_.is("+");
    if (!add && !cur_.is("-")) {
      unget_ = true;
      return l;
    }
    const SourceLoc at = cur_.loc();
    l = binary(add ? FnOp::Add : FnOp::Sub, l, fnProduct(s), at);
  }
}

FnNodePtr TokenStream::fnProduct(FnScope& s) {
  FnNodePtr l = fnUnary(s);
  for (;;) {
    getToken();
    const bool mul = cur_.is("*");
    if (!mul && !cur_.is("/")) {
      unget_ = true;
      return l;
    }
    const Token op = cur_;
    FnNodePtr r = fnUnary(s);
    if (!mul && isConstant(r) && !isConstant(l)) {
      // POV-Ray multiplies by the reciprocal, and refuses a constant 0 divisor.
      if (r->value == 0.0) error(op, "division by zero");
      r = constant(1.0 / r->value, r->loc);
      l = binary(FnOp::Mul, l, r, op.loc());
      continue;
    }
    l = binary(mul ? FnOp::Mul : FnOp::Div, l, r, op.loc());
  }
}

FnNodePtr TokenStream::fnUnary(FnScope& s) {
  Nesting nesting(*this);
  getToken();
  if (cur_.is("+")) return fnUnary(s);
  if (cur_.is("-")) {
    const SourceLoc at = cur_.loc();
    FnNodePtr a = fnUnary(s);
    if (isConstant(a)) return constant(-a->value, at);
    return node(FnOp::Neg, {a}, at);
  }
  unget_ = true;
  return fnPrimary(s);
}

FnNodePtr TokenStream::fnPrimary(FnScope& s) {
  getToken();
  const SourceLoc at = cur_.loc();
  switch (cur_.kind) {
    case TokenKind::Number:
      return constant(cur_.number(), at);
    case TokenKind::Punct:
      if (cur_.is("(")) {
        FnNodePtr e = fnOr(s);
        expect(")");
        return e;
      }
      if (cur_.is("!")) error(cur_, "'!' is not in POV-Ray's function language");
      break;
    case TokenKind::Keyword:
      switch (cur_.kw) {
        case Kw::k_pi:
          return constant(kPi, at);
        case Kw::k_clock:
          return constant(options_.clock, at);
        case Kw::k_x:
        case Kw::k_u:
        case Kw::k_y:
        case Kw::k_v:
        case Kw::k_z: {
          const int reg = cur_.kw == Kw::k_x || cur_.kw == Kw::k_u   ? s.xReg
                          : cur_.kw == Kw::k_y || cur_.kw == Kw::k_v ? s.yReg
                                                                     : s.zReg;
          auto n = node(FnOp::Param, {}, at);
          std::const_pointer_cast<FnNode>(n)->index = reg;
          return n;
        }
        default:
          return fnBuiltin(s);
      }
    case TokenKind::Undeclared:
      return fnName(s);
    case TokenKind::Identifier: {
      const Value* v = cur_.value();
      if (v && v->type == ValueType::Float) return constant(v->v[0], at);
      if (v && v->type == ValueType::Function) return fnUserCall(s);
      error(cur_, "a function can use float identifiers, not the " + cur_.describe());
    }
    default:
      break;
  }
  error(cur_, "expected a number, a parameter, a function call or '(' in the function, found " +
                  cur_.describe());
}

// An undeclared name: a sum() or prod() variable, or a parameter.
FnNodePtr TokenStream::fnName(FnScope& s) {
  const std::string name(cur_.text());
  const SourceLoc at = cur_.loc();
  for (auto it = s.locals.rbegin(); it != s.locals.rend(); ++it)
    if (it->first == name) {
      auto n = std::make_shared<FnNode>();
      n->op = FnOp::Local;
      n->index = it->second;
      n->loc = at;
      return n;
    }
  for (int i = 0; i < s.f.arity(); ++i)
    if (s.f.params[static_cast<size_t>(i)] == name) {
      auto n = std::make_shared<FnNode>();
      n->op = FnOp::Param;
      n->index = i;
      n->loc = at;
      return n;
    }
  if (rawPeek().kind == RawKind::Punct && rawPeek().text == "(")
    error(cur_, "unknown function '" + name +
                    "' (declare it first; POV-Ray's internal functions are declared by "
                    "functions.inc)");
  error(cur_, "'" + name + "' is neither a parameter of the function nor a declared float");
}

// `( a, b, ... )`: each argument an expression of the function language.
std::vector<FnNodePtr> TokenStream::fnArguments(FnScope& s) {
  expect("(");
  std::vector<FnNodePtr> args;
  args.push_back(fnOr(s));
  while (allow(",")) args.push_back(fnOr(s));
  expect(")");
  return args;
}

// A built-in function: sin(...), min(...), select(...), sum(i, a, b, expr)...
FnNodePtr TokenStream::fnBuiltin(FnScope& s) {
  const Token at = cur_;
  const std::string name(at.text());
  auto count = [&](size_t given, size_t lo, size_t hi) {
    if (given >= lo && given <= hi) return;
    const std::string want = lo == hi         ? std::to_string(lo)
                             : hi == SIZE_MAX ? std::to_string(lo) + " or more"
                                              : std::to_string(lo) + " or " + std::to_string(hi);
    error(at, "'" + name + "' takes " + want + " argument" + (hi == 1 ? "" : "s") + ", " +
                  std::to_string(given) + " given");
  };
  for (const MathWord& m : kMathWords) {
    if (m.kw != at.kw) continue;
    std::vector<FnNodePtr> args = fnArguments(s);
    const size_t arity = static_cast<size_t>(fnMathArity(m.math));
    count(args.size(), arity, arity);
    if (m.math == FnMath::Pow && isConstant(args[1])) {
      const double e = args[1]->value;
      if (isConstant(args[0])) return constant(std::pow(args[0]->value, e), at.loc());
      if (e == 0.0) {
        warning(at.loc(), "zero power optimised to constant 1.0 (as POV-Ray does)");
        return constant(1.0, at.loc());
      }
      if (e >= 2.0 && e <= 8.0 && e == std::floor(e))
        return power(args[0], static_cast<int>(e), at.loc());
    }
    if (arity == 1 && isConstant(args[0]) && m.math != FnMath::Div) {
      // Folded now, with POV-Ray's formulas (its ln and log of a number <= 0 are errors).
      const double x = args[0]->value;
      if ((m.math == FnMath::Ln || m.math == FnMath::Log) && !(x > 0.0))
        error(at, "domain error in '" + name + "'");
      double v;
      if (m.math == FnMath::Radians) v = x * kPi / 180.0;
      else if (m.math == FnMath::Degrees) v = x * 180.0 / kPi;
      else v = fnMath(m.math, x, 0.0);
      return constant(v, at.loc());
    }
    auto n = node(FnOp::Math, std::move(args), at.loc());
    std::const_pointer_cast<FnNode>(n)->index = static_cast<int>(m.math);
    return n;
  }
  switch (at.kw) {
    case Kw::k_min:
    case Kw::k_max: {
      std::vector<FnNodePtr> args = fnArguments(s);
      count(args.size(), 2, SIZE_MAX);
      return node(at.kw == Kw::k_min ? FnOp::Min : FnOp::Max, std::move(args), at.loc());
    }
    case Kw::k_select: {
      std::vector<FnNodePtr> args = fnArguments(s);
      count(args.size(), 3, 4);
      return node(FnOp::Select, std::move(args), at.loc());
    }
    case Kw::k_sum:
    case Kw::k_prod: {
      expect("(");
      getToken();
      if (cur_.kind != TokenKind::Undeclared)
        error(cur_, "expected the name of " + name + "()'s variable, found " + cur_.describe());
      const int slot = s.f.locals++;
      s.locals.emplace_back(std::string(cur_.text()), slot);
      std::vector<FnNodePtr> args;
      for (int i = 0; i < 3; ++i) {
        expect(",");
        args.push_back(fnOr(s));
      }
      expect(")");
      s.locals.pop_back();
      auto n = node(at.kw == Kw::k_sum ? FnOp::Sum : FnOp::Prod, std::move(args), at.loc());
      std::const_pointer_cast<FnNode>(n)->index = slot;
      return n;
    }
    default:
      error(at, "'" + name +
                    "' cannot be used in a function (POV-Ray's function language has "
                    "numbers, parameters, float identifiers, pi, clock, + - * /, "
                    "comparisons, & |, and its own list of functions)");
  }
}

// A declared function called in the body: f(a, b, ...), and `.x` after a vector function.
FnNodePtr TokenStream::fnUserCall(FnScope& s) {
  const Token at = cur_;
  const std::string name(at.text());
  std::shared_ptr<const FunctionValue> callee = at.value()->function;
  if (!s.self.empty() && name == s.self)
    error(at, "recursive function calls are not allowed ('" + name +
                  "' calls itself; POV-Ray refuses it too)");
  std::vector<FnNodePtr> args = fnArguments(s);
  if (static_cast<int>(args.size()) != callee->arity())
    error(at, "'" + name + "' takes " + std::to_string(callee->arity()) + " argument" +
                  (callee->arity() == 1 ? "" : "s") + ", " + std::to_string(args.size()) +
                  " given");
  auto n = std::make_shared<FnNode>();
  n->op = FnOp::Call;
  n->args = std::move(args);
  n->callee = callee;
  n->loc = at.loc();
  n->depth = depthOf(*n);
  getToken();
  if (cur_.is(".")) {
    getToken();
    const int member = memberIndex(cur_);
    if (member < 0)
      error(cur_,
            "expected x, y, z, t, u, v, red, green, blue, gray, grey, filter, transmit or hf "
            "after '.', found " +
                cur_.describe());
    if ((callee->kind != FunctionValue::Kind::Unsupported &&
         callee->kind != FunctionValue::Kind::Spline &&
         callee->kind != FunctionValue::Kind::Pigment &&
         callee->kind != FunctionValue::Kind::Transform) ||
        callee->what == "a pattern function")
      error(cur_, "'." + std::string(cur_.text()) + "' of '" + name +
                      "', which gives a float, not a vector");
    n->member = member;
  } else {
    unget_ = true;
    // A pattern function's value: its pigment's red.
    if (callee->kind == FunctionValue::Kind::Pigment && callee->what == "a pattern function")
      n->member = 0;
    if (callee->kind == FunctionValue::Kind::Spline)
      error(at, "'" + name +
                    "' is a spline function: it gives a vector, so a function takes one of its "
                    "components ('.x', '.red'...)");
    if ((callee->kind == FunctionValue::Kind::Unsupported ||
         callee->kind == FunctionValue::Kind::Pigment ||
         callee->kind == FunctionValue::Kind::Transform) &&
        callee->what != "a pattern function")
      error(at, "'" + name + "' is " + callee->what +
                    ": it gives a vector, so a function takes one of its components "
                    "('.x', '.red'...)");
  }
  return n;
}

// f(a, b, c) in an expression, f the current token: POV-Ray evaluates it now. A pigment
// function gives its colour (five terms, as POV-Ray's call of one does), others a float.
void TokenStream::functionCall(Express& e, int& terms) {
  const Token at = cur_;
  const std::shared_ptr<const FunctionValue> f = at.value()->function;
  const std::string name(at.text());
  expect("(");
  std::vector<double> args;
  if (!allow(")")) {
    for (;;) {
      args.push_back(parseFloat());
      if (allow(")")) break;
      parseComma();
    }
  }
  if (static_cast<int>(args.size()) != f->arity())
    error(at, "'" + name + "' takes " + std::to_string(f->arity()) + " argument" +
                  (f->arity() == 1 ? "" : "s") + ", " + std::to_string(args.size()) + " given");
  try {
    PigmentValue pigments;
    if (items_)
      pigments = [this](const FunctionValue& fn, int member, const double* xyz) {
        return items_->pigmentValue(fn, member, xyz);
      };
    if (f->kind == FunctionValue::Kind::Pigment && f->what != "a pattern function") {
      for (int i = 0; i < 5; ++i) e.v[i] = evaluateFunction(*f, args, pigments, i);
      terms = 5;
      return;
    }
    if (f->kind == FunctionValue::Kind::Transform) {  // a vector
      for (int i = 0; i < 3; ++i) e.v[i] = evaluateFunction(*f, args, pigments, i);
      terms = 3;
      return;
    }
    const double v = evaluateFunction(*f, args, pigments);
    for (int i = 0; i < terms; ++i) e.v[i] = v;
  } catch (const FunctionError& err) {
    std::string m = err.what();
    if (err.at.line > 0)
      m += "\n" + err.at.str() + ": note: the cause, in the function's declaration";
    error(at, m);
  }
}

}  // namespace lucent::sdl
