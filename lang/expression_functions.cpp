#include "expression_functions.h"

#include "scenegraph/internal_functions.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace lucent {

namespace {

thread_local ExpressionFault tFault;

// Thrown by a twin (ParserRole::Locating) when its own operation faults.
struct FaultHere {};

std::string num(double v) { return fmt::format("{}", v); }

bool finite(double a) { return std::isfinite(a); }

// --- operators ---------------------------------------------------------------------------
double addOp(double a, double b) { return a + b; }
double subOp(double a, double b) { return a - b; }
double mulOp(double a, double b) { return a * b; }
double divOp(double a, double b) { return a / b; }
double modOp(double a, double b) { return flooredModulo(a, b); }
double powOp(double a, double b) { return std::pow(a, b); }

using F1 = double (*)(double);
using F2 = double (*)(double, double);
using F3 = double (*)(double, double, double);

// A binary arithmetic operator: `symbol` names it in messages.
template <F2 f, char symbol, bool Twin>
double binary(double a, double b) {
  double r = f(a, b);
  if (finite(a) && finite(b) && !std::isfinite(r)) {
    // A twin records its message too: muParser folds constant parts when it compiles, so
    // the plain evaluation of a cached expression may not call this again.
    if (!tFault.happened || Twin) {
      tFault.happened = true;
      if ((symbol == '/' || symbol == '%') && b == 0.0)
        tFault.what = fmt::format("division by zero ({} {} {})", num(a), symbol, num(b));
      else tFault.what = fmt::format("{} {} {} is not a finite number", num(a), symbol, num(b));
    }
    if (Twin) throw FaultHere{};
  }
  return r;
}

double lorOp(double a, double b) { return (a != 0.0 || b != 0.0) ? 1.0 : 0.0; }
double landOp(double a, double b) { return (a != 0.0 && b != 0.0) ? 1.0 : 0.0; }
double eqOp(double a, double b) { return a == b ? 1.0 : 0.0; }
double neOp(double a, double b) { return a != b ? 1.0 : 0.0; }
double ltOp(double a, double b) { return a < b ? 1.0 : 0.0; }
double leOp(double a, double b) { return a <= b ? 1.0 : 0.0; }
double gtOp(double a, double b) { return a > b ? 1.0 : 0.0; }
double geOp(double a, double b) { return a >= b ? 1.0 : 0.0; }
double negOp(double a) { return -a; }
double notOp(double a) { return a == 0.0 ? 1.0 : 0.0; }

// --- functions ---------------------------------------------------------------------------
double fSin(double x) { return std::sin(x); }
double fCos(double x) { return std::cos(x); }
double fTan(double x) { return std::tan(x); }
double fAsin(double x) { return std::asin(x); }
double fAcos(double x) { return std::acos(x); }
double fAtan(double x) { return std::atan(x); }
double fSqrt(double x) { return std::sqrt(x); }
double fExp(double x) { return std::exp(x); }
double fLn(double x) { return std::log(x); }
double fLog10(double x) { return std::log10(x); }
double fLog2(double x) { return std::log2(x); }
double fAbs(double x) { return std::fabs(x); }
double fSign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }
double fFloor(double x) { return std::floor(x); }
double fCeil(double x) { return std::ceil(x); }
double fRound(double x) { return std::round(x); }  // halves away from zero
double fTrunc(double x) { return std::trunc(x); }
double fRadians(double d) { return d * (M_PI / 180.0); }
double fDegrees(double r) { return r * (180.0 / M_PI); }
double fAtan2(double y, double x) { return std::atan2(y, x); }
double fPow(double x, double y) { return std::pow(x, y); }
double fClamp(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }
double fMix(double a, double b, double t) { return a + (b - a) * t; }

template <bool Twin>
void noteFunction(const char* name, std::initializer_list<double> args, double r) {
  for (double a : args)
    if (!finite(a)) return;
  if (std::isfinite(r)) return;
  if (tFault.happened && !Twin) return;
  std::string list;
  for (double a : args) list += (list.empty() ? "" : ", ") + num(a);
  tFault.happened = true;
  tFault.what = fmt::format("{}({}) is not a finite number", name, list);
  if (Twin) throw FaultHere{};
}

template <F1 f, const char* name, bool Twin>
double fun1(double a) {
  double r = f(a);
  noteFunction<Twin>(name, {a}, r);
  return r;
}
template <F2 f, const char* name, bool Twin>
double fun2(double a, double b) {
  double r = f(a, b);
  noteFunction<Twin>(name, {a, b}, r);
  return r;
}
template <F3 f, const char* name, bool Twin>
double fun3(double a, double b, double c) {
  double r = f(a, b, c);
  noteFunction<Twin>(name, {a, b, c}, r);
  return r;
}
double fMin(const double* a, int n) {
  double m = a[0];
  for (int i = 1; i < n; ++i) m = std::min(m, a[i]);
  return m;
}
double fMax(const double* a, int n) {
  double m = a[0];
  for (int i = 1; i < n; ++i) m = std::max(m, a[i]);
  return m;
}

constexpr char kSin[] = "sin", kCos[] = "cos", kTan[] = "tan", kAsin[] = "asin", kAcos[] = "acos",
               kAtan[] = "atan", kAtan2[] = "atan2", kSqrt[] = "sqrt", kExp[] = "exp", kLn[] = "ln",
               kLog10[] = "log10", kLog2[] = "log2", kAbs[] = "abs", kSign[] = "sign",
               kFloor[] = "floor", kCeil[] = "ceil", kRound[] = "round", kTrunc[] = "trunc",
               kPow[] = "pow", kClamp[] = "clamp", kMix[] = "mix", kRadians[] = "radians",
               kDegrees[] = "degrees", kRandom[] = "random";

// One of POV-Ray's internal functions (functions.inc's f_sphere...) that Lucent evaluates in
// closed form, called with its arguments (muParser hands the function's table row back).
template <bool Twin, class... D>
double internalCall(void* row, D... a) {
  const auto* f = static_cast<const InternalFunction*>(row);
  const double p[] = {a...};
  const double r = f->evaluate(p);
  noteFunction<Twin>(f->name, {a...}, r);
  return r;
}
template <size_t, class T>
using Same = T;
template <bool Twin, size_t... I>
void defineInternal(mu::Parser& p, const std::string& name, const InternalFunction* f,
                    std::index_sequence<I...>) {
  p.DefineFunUserData(name, internalCall<Twin, Same<I, double>...>,
                      const_cast<InternalFunction*>(f));
}
template <bool Twin, size_t N = 1>
void defineInternalOfArity(mu::Parser& p, const std::string& name, const InternalFunction* f) {
  if (static_cast<size_t>(f->params) == N)
    defineInternal<Twin>(p, name, f, std::make_index_sequence<N>{});
  else if constexpr (N < 10) defineInternalOfArity<Twin, N + 1>(p, name, f);
}

template <bool Twin>
void defineFunctions(mu::Parser& p, const std::string& prefix) {
  for (const InternalFunction* f : evaluatedInternalFunctions())
    defineInternalOfArity<Twin>(p, prefix + f->name, f);
  p.DefineFun(prefix + kSin, fun1<fSin, kSin, Twin>);
  p.DefineFun(prefix + kCos, fun1<fCos, kCos, Twin>);
  p.DefineFun(prefix + kTan, fun1<fTan, kTan, Twin>);
  p.DefineFun(prefix + kAsin, fun1<fAsin, kAsin, Twin>);
  p.DefineFun(prefix + kAcos, fun1<fAcos, kAcos, Twin>);
  p.DefineFun(prefix + kAtan, fun1<fAtan, kAtan, Twin>);
  p.DefineFun(prefix + kAtan2, fun2<fAtan2, kAtan2, Twin>);
  p.DefineFun(prefix + kSqrt, fun1<fSqrt, kSqrt, Twin>);
  p.DefineFun(prefix + kExp, fun1<fExp, kExp, Twin>);
  p.DefineFun(prefix + kLn, fun1<fLn, kLn, Twin>);
  p.DefineFun(prefix + kLog10, fun1<fLog10, kLog10, Twin>);
  p.DefineFun(prefix + kLog2, fun1<fLog2, kLog2, Twin>);
  p.DefineFun(prefix + kAbs, fun1<fAbs, kAbs, Twin>);
  p.DefineFun(prefix + kSign, fun1<fSign, kSign, Twin>);
  p.DefineFun(prefix + kFloor, fun1<fFloor, kFloor, Twin>);
  p.DefineFun(prefix + kCeil, fun1<fCeil, kCeil, Twin>);
  p.DefineFun(prefix + kRound, fun1<fRound, kRound, Twin>);
  p.DefineFun(prefix + kTrunc, fun1<fTrunc, kTrunc, Twin>);
  p.DefineFun(prefix + kPow, fun2<fPow, kPow, Twin>);
  p.DefineFun(prefix + kClamp, fun3<fClamp, kClamp, Twin>);
  p.DefineFun(prefix + kMix, fun3<fMix, kMix, Twin>);
  p.DefineFun(prefix + kRadians, fun1<fRadians, kRadians, Twin>);
  p.DefineFun(prefix + kDegrees, fun1<fDegrees, kDegrees, Twin>);
  p.DefineFun(prefix + kRandom, fun2<sceneRandom, kRandom, Twin>);
  p.DefineFun(prefix + "min", fMin);  // finite arguments give a finite result
  p.DefineFun(prefix + "max", fMax);
}

// Precedences, lowest first (the ternary ?: is muParser's own, below all of them).
enum Precedence { kOr = 1, kAnd, kEquality, kOrder, kSum, kProduct, kUnary, kPower };

// muParser takes no unary operator right after another ("--x", "!-x", "!!x"), which the
// language allows: each run of two to four of them is defined as one operator that applies
// them from right to left. Bit k of Bits is the k-th operator from the right: 1 is '!'.
template <unsigned Bits, unsigned Len>
double unaryRun(double x) {
  for (unsigned k = 0; k < Len; ++k) x = (Bits >> k & 1u) ? (x == 0.0 ? 1.0 : 0.0) : -x;
  return x;
}

std::string unaryRunName(unsigned bits, unsigned len) {
  std::string s(len, '-');
  for (unsigned i = 0; i < len; ++i)
    if (bits >> (len - 1 - i) & 1u) s[i] = '!';
  return s;
}

template <unsigned Len, unsigned... B>
void defineUnaryRuns(mu::Parser& p, std::integer_sequence<unsigned, B...>) {
  (p.DefineInfixOprt(unaryRunName(B, Len), unaryRun<B, Len>, kUnary), ...);
}

template <bool Twin>
void defineFaultingOperators(mu::Parser& p, bool twinSymbols) {
  auto name = [&](char op) {
    if (!twinSymbols) return std::string(1, op);
    for (const OperatorTwin& t : faultingOperators())
      if (t.op == op) return std::string(1, t.twin);
    return std::string(1, op);
  };
  p.DefineOprt(name('+'), binary<addOp, '+', Twin>, kSum, mu::oaLEFT, true);
  p.DefineOprt(name('-'), binary<subOp, '-', Twin>, kSum, mu::oaLEFT, true);
  p.DefineOprt(name('*'), binary<mulOp, '*', Twin>, kProduct, mu::oaLEFT, true);
  p.DefineOprt(name('/'), binary<divOp, '/', Twin>, kProduct, mu::oaLEFT, true);
  p.DefineOprt(name('%'), binary<modOp, '%', Twin>, kProduct, mu::oaLEFT, true);
  p.DefineOprt(name('^'), binary<powOp, '^', Twin>, kPower, mu::oaRIGHT, true);
}

}  // namespace

ExpressionFault& currentExpressionFault() { return tFault; }

const std::vector<OperatorTwin>& faultingOperators() {
  // Printable characters that expressions never hold: muParser skips every character up
  // to ' ' as white space, so control characters would vanish instead of naming a twin.
  static const std::vector<OperatorTwin> ops{{'+', '#'},  {'-', '~'}, {'*', '`'},
                                             {'/', '\''}, {'%', '['}, {'^', ']'}};
  return ops;
}

const std::vector<std::string_view>& expressionFunctionNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> v{"sin",   "cos",  "tan",     "asin",    "acos",  "atan", "atan2",
                                    "sqrt",  "exp",  "ln",      "log10",   "log2",  "abs",  "sign",
                                    "floor", "ceil", "round",   "trunc",   "pow",   "min",  "max",
                                    "clamp", "mix",  "radians", "degrees", "random"};
    // POV-Ray's functions.inc functions that Lucent evaluates (f_sphere, f_rounded_box...).
    for (const InternalFunction* f : evaluatedInternalFunctions()) v.emplace_back(f->name);
    return v;
  }();
  return names;
}

void defineLanguage(mu::Parser& p, ParserRole role) {
  p.EnableBuiltInOprt(false);  // every operator below, with the contract's precedences
  // No constant folding: it would call the functions once, while the expression is first
  // compiled, so a fault in a constant part ("1 || 1/0") was reported by the first
  // evaluation only and every later one (from the cache) gave a number.
  p.EnableOptimizer(false);
  p.ClearFun();
  p.ClearConst();  // pi and e are names the scene may hide with its own parameters
  p.ClearInfixOprt();
  p.ClearPostfixOprt();
  if (role == ParserRole::Locating) {
    std::string oprt = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ+-*^/?<>=#!$%&|~'_{}";
    for (const OperatorTwin& t : faultingOperators()) oprt += t.twin;
    p.DefineOprtChars(oprt.c_str());
    std::string nameChars = "0123456789_abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
    nameChars += kFunctionTwinPrefix;
    p.DefineNameChars(nameChars.c_str());
  }
  p.DefineOprt("||", lorOp, kOr, mu::oaLEFT, true);
  p.DefineOprt("&&", landOp, kAnd, mu::oaLEFT, true);
  p.DefineOprt("==", eqOp, kEquality, mu::oaLEFT, true);
  p.DefineOprt("!=", neOp, kEquality, mu::oaLEFT, true);
  p.DefineOprt("<", ltOp, kOrder, mu::oaLEFT, true);
  p.DefineOprt("<=", leOp, kOrder, mu::oaLEFT, true);
  p.DefineOprt(">", gtOp, kOrder, mu::oaLEFT, true);
  p.DefineOprt(">=", geOp, kOrder, mu::oaLEFT, true);
  defineFaultingOperators<false>(p, false);
  p.DefineInfixOprt("-", negOp, kUnary);
  p.DefineInfixOprt("!", notOp, kUnary);
  defineUnaryRuns<2>(p, std::make_integer_sequence<unsigned, 4>{});
  defineUnaryRuns<3>(p, std::make_integer_sequence<unsigned, 8>{});
  defineUnaryRuns<4>(p, std::make_integer_sequence<unsigned, 16>{});
  defineFunctions<false>(p, "");
  if (role == ParserRole::Locating) {
    defineFaultingOperators<true>(p, true);
    defineFunctions<true>(p, std::string(1, kFunctionTwinPrefix));
  }
}

double flooredModulo(double a, double b) {
  double r = std::fmod(a, b);
  if (r != 0.0 && ((r < 0.0) != (b < 0.0))) r += b;
  return r;
}

double sceneRandom(double seed, double i) {
  auto bits = [](double v) {
    if (v == 0.0) v = 0.0;  // -0 and 0 are the same argument
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  };
  // SplitMix64's finaliser (Steele, Lea and Flood 2014) over both arguments: every output
  // bit depends on every input bit, in integer arithmetic only.
  auto mix = [](std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  std::uint64_t h = mix(bits(seed) + 0x9e3779b97f4a7c15ULL);
  h = mix(h ^ (bits(i) + 0x632be59bd9b4e019ULL));
  return static_cast<double>(h >> 11) * 0x1.0p-53;  // 53 bits: [0, 1)
}

}  // namespace lucent
