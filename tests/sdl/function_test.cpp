// POV-Ray's user-defined functions in the language core (sdl/function.h): declarations,
// calls evaluated in expressions, the internal functions of functions.inc that have closed
// forms (exact values, and their Lucent expression text against their C++ formula), the
// text an isosurface gets, and every error located inside the function's text.
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

#include "scenegraph/internal_functions.h"
#include "sdl/function.h"

#include "lang/expression.h"
#include "lang/expression_field.h"

#include <cmath>
#include <cstdio>

using namespace lucent;
using namespace lucent::sdl;

namespace {

// The value `name` has after `text` is evaluated.
Value valueAfter(const std::string& text, const std::string& name) {
  CollectedOutput out;
  Options options;
  options.output = &out;
  sdltest::SkippingItemReader items;
  TokenStream in(options, &items);
  in.openText("test.pov", text, sdltest::dataFolder());
  for (;;) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) break;
    REQUIRE(t.kind == TokenKind::Keyword);
    items.read(t, in);
  }
  const Value* v = in.lookup(name);
  REQUIRE(v);
  return *v;
}

double numberAfter(const std::string& text) {
  const Value v = valueAfter(text + "\n#declare Result = " + "R;\n", "Result");
  REQUIRE(v.type == ValueType::Float);
  return v.v[0];
}

const std::string kFunctions = "#version 3.7;\n#include \"functions.inc\"\n";

}  // namespace

TEST_CASE("sdl function: declared, called with numbers, with POV-Ray's parameter rules",
          "[sdl][function]") {
  CHECK(numberAfter("#declare F = function(a, b, c) { a*b + c }\n#declare R = F(2, 3, 4);") ==
        10.0);
  // No parameter list: x, y, z. Commas between a call's arguments are optional in SDL.
  CHECK(numberAfter("#declare F = function { x*100 + y*10 + z }\n#declare R = F(1 2, 3);") ==
        123.0);
  // x (or u), y (or v) and z are the parameters of those names, 0 when there is none.
  CHECK(numberAfter("#declare F = function(a, b) { x + 10*y + a }\n#declare R = F(1, 2);") == 1.0);
  CHECK(numberAfter("#declare F = function(u, v) { x + 10*y }\n#declare R = F(1, 2);") == 21.0);
  CHECK(numberAfter("#declare F = function(z, y, x) { x }\n#declare R = F(1, 2, 3);") == 3.0);
  // A declared float is folded in when the function is declared.
  CHECK(numberAfter("#declare K = 2;\n#declare F = function { K*x }\n#declare K = 5;\n"
                    "#declare R = F(3, 0, 0);") == 6.0);
  CHECK(numberAfter("#declare F = function { pi*x }\n#declare R = F(2, 0, 0);") == 2 * M_PI);
  // A function passed to a macro, called in its body (read where the macro is called, so
  // 2*M(F, 3) is 2*F(3) + 1, as in POV-Ray).
  CHECK(numberAfter("#declare F = function(a) { a*a }\n#macro M(G, w) G(w) + 1 #end\n"
                    "#declare R = 2*M(F, 3);") == 19.0);
  // Given to a macro as its argument, and declared with #local.
  CHECK(numberAfter("#macro M(G) G(3, 0, 0) #end\n#declare R = M(function { x*2 });") == 6.0);
  CHECK(numberAfter("#macro M() #local L = function { x + 1 } L(1, 0, 0) #end\n"
                    "#declare R = M();") == 2.0);
  // Kept in an array, and called from it.
  CHECK(numberAfter("#declare A = array[2] { function { x }, function { y } }\n"
                    "#declare R = A[1](1, 2, 3) + 10*A[0](1, 2, 3);") == 12.0);
  // Copied by #declare.
  CHECK(numberAfter("#declare F = function(a) { a + 1 }\n#declare G = F;\n#declare R = G(1);") ==
        2.0);
}

TEST_CASE("sdl function: operators, precedence and POV-Ray's built-in functions",
          "[sdl][function]") {
  auto f = [](const std::string& body, const std::string& args) {
    return numberAfter("#declare F = function { " + body + " }\n#declare R = F(" + args + ");");
  };
  CHECK(f("1 | 1 & 0", "0,0,0") == 1.0);  // & binds above |
  CHECK(f("1 < 2 < 3", "0,0,0") == 1.0);  // comparisons at one level, left to right
  CHECK(f("x = 2", "2,0,0") == 1.0);
  CHECK(f("x != 2", "2,0,0") == 0.0);
  CHECK(f("-x*-2", "1,0,0") == 2.0);
  CHECK(f("select(x, 1, 2)", "-1,0,0") == 1.0);
  CHECK(f("select(x, 1, 2)", "0,0,0") == 2.0);
  CHECK(f("select(x, 1, 2, 3)", "0,0,0") == 2.0);
  CHECK(f("select(x, 1, 2, 3)", "5,0,0") == 3.0);
  CHECK(f("sum(i, 1, 4, i*x)", "2,0,0") == 20.0);
  CHECK(f("prod(i, 1, 4, i)", "0,0,0") == 24.0);
  CHECK(f("min(x, y, z) + max(x, y, z)", "3,-1,2") == 2.0);
  CHECK(f("int(x) + div(7, 2) + mod(7, x)", "-2.5,0,0") == -2.0 + 3.0 + 2.0);
  CHECK(f("atan2(x, y)", "1,1,0") == std::atan2(1.0, 1.0));
  CHECK(f("log(x) + ln(y)", "100,1,0") == 2.0);
  // a / c is a * (1/c), as POV-Ray's compiler writes it; pow(a, 3) is (a*a)*a.
  CHECK(f("x/3", "1,0,0") == 1.0 * (1.0 / 3.0));
  CHECK(f("pow(x, 3)", "1.1,0,0") == (1.1 * 1.1) * 1.1);
  // A division by zero at run time gives IEEE's infinity, as in POV-Ray 3.7.
  CHECK(std::isinf(numberAfter("#declare F = function(a, b) { a/b }\n#declare R = F(1, 0);")));
}

TEST_CASE("sdl function: functions calling functions", "[sdl][function]") {
  CHECK(numberAfter("#declare A = function(p) { p*2 }\n#declare B = function(q) { A(q) + A(q+1) }\n"
                    "#declare C = function { B(x) * B(y) }\n#declare R = C(1, 2, 0);") ==
        (2.0 + 4.0) * (4.0 + 6.0));
}

TEST_CASE("sdl function: functions.inc's closed forms give exact values", "[sdl][function]") {
  auto v = [](const std::string& call) {
    return numberAfter(kFunctions + "#declare R = " + call + ";");
  };
  CHECK(v("f_sphere(3, 4, 0, 1)") == 4.0);
  CHECK(v("f_r(3, 4, 12)") == 13.0);
  CHECK(v("f_th(1, 0, 0)") == std::atan2(1.0, 0.0));
  CHECK(v("f_ph(0, 1, 0)") == 0.0);
  CHECK(v("f_torus(2, 0, 0, 1.5, 0.25)") == 0.25);
  CHECK(v("f_rounded_box(1, 0, 0, 0.125, 0.5, 0.5, 0.5)") == 0.5 - 1e-6);
  CHECK(v("f_superellipsoid(1, 0, 0, 1, 1)") == 0.0);
  CHECK(v("f_ellipsoid(1, 2, 2, 2, 1, 0.5)") == 3.0);
  CHECK(v("f_paraboloid(1, 0, 1, 100)") == -10.0);  // clamped to [-10, 10]
  CHECK(v("f_umbrella(1, 2, 3, 0.5)") == 0.5 * -(1.0 - 18.0));
  CHECK(v("f_witch_of_agnesi(0, 1, 0, 1, 0.5)") == 0.0);
}

namespace {
// Expression names for a function's text: none besides x, y and z.
struct NoNames : ExpressionNames {
  std::optional<double> number(std::string_view, std::string& e, bool& known) override {
    known = false;
    e = "none";
    return std::nullopt;
  }
  std::vector<std::string> visibleNames() override { return {}; }
};
}  // namespace

TEST_CASE("sdl function: each internal formula's Lucent text gives its C++ value",
          "[sdl][function]") {
  const double points[][3] = {{0.3, -0.2, 0.7}, {1.1, 0.4, -0.6}, {-0.05, 0.9, 0.25}};
  const char* params[] = {"0.7", "0.45", "0.6", "0.35", "0.8", "0.55", "0.3"};
  const double values[] = {0.7, 0.45, 0.6, 0.35, 0.8, 0.55, 0.3};
  // (Each formula at these points with these parameters, C++ against text.)
  int checked = 0;
  for (int n = 0; internalFunction(n); ++n) {
    const InternalFunction* in = internalFunction(n);
    if (!in->evaluate) {
      CHECK(!in->text);
      continue;
    }
    INFO(in->name);
    FunctionValue f;
    f.kind = FunctionValue::Kind::Internal;
    f.internal = n;
    std::vector<std::string> args = {"x", "y", "z"};
    for (int i = 3; i < in->params; ++i) args.push_back(params[i - 3]);
    // The importer writes a call of the expression language's function of that name; the
    // formula is what export-pov writes out.
    const std::string call = functionText(f, args);
    std::string wantCall = std::string(in->name) + "(";
    for (size_t i = 0; i < args.size(); ++i) wantCall += (i ? ", " : "") + args[i];
    CHECK(call == wantCall + ")");
    const std::string text = internalFormula(*in, args);
    NoNames names;
    ExpressionError problem;
    auto compiled = compileFunction(text, {"x", "y", "z"}, names, problem);
    INFO(text << " " << problem.message);
    REQUIRE(compiled);
    auto compiledCall = compileFunction(call, {"x", "y", "z"}, names, problem);
    REQUIRE(compiledCall);
    auto field = makeExpressionField(*compiled);
    auto callField = makeExpressionField(*compiledCall);
    for (const auto& p : points) {
      double all[10] = {p[0], p[1], p[2]};
      for (int i = 3; i < in->params; ++i) all[i] = values[i - 3];
      CHECK(field->value(Vec3(p[0], p[1], p[2])) == Approx(in->evaluate(all)).margin(1e-12));
      CHECK(callField->value(Vec3(p[0], p[1], p[2])) == in->evaluate(all));
    }
    ++checked;
  }
  CHECK(checked == 40);
}

TEST_CASE("sdl function: f_helix1's text gives its C++ value for each cross-section",
          "[sdl][function]") {
  const int n = 25;
  const InternalFunction* in = internalFunction(n);
  REQUIRE(std::string(in->name) == "f_helix1");
  REQUIRE(in->evaluate);
  // Circles, a rounded rectangle turned 30 degrees, a square, a diamond, a turn of -45.
  const double params[][7] = {{3, 35, 0.0105, 0.0165, 2, 1, 0},
                              {2, 1.5, 0.1, 0.9, 1.3, 0.5, 30},
                              {1, 2, 0.2, 0.7, 1, 0, 0},
                              {4, 0.8, 0.15, 0.6, 0.7, 2, 0},
                              {2, 1.1, 0.1, 0.5, 1, 0.3, -45}};
  const double points[][3] = {
      {0.8, 0.3, 0.5}, {-0.6, -1.7, 0.45}, {0, 0.35, 0}, {-0.3, -2.2, -0.4}};
  for (const auto& q : params) {
    FunctionValue f;
    f.kind = FunctionValue::Kind::Internal;
    f.internal = n;
    std::vector<std::string> args = {"x", "y", "z"};
    for (double v : q) {
      char number[40];
      std::snprintf(number, sizeof number, "(%.17g)", v);
      args.push_back(number);
    }
    const std::string text = functionText(f, args);
    NoNames names;
    ExpressionError problem;
    auto compiled = compileFunction(text, {"x", "y", "z"}, names, problem);
    INFO(text << " " << problem.message);
    REQUIRE(compiled);
    auto field = makeExpressionField(*compiled);
    for (const auto& p : points) {
      double all[10] = {p[0], p[1], p[2], q[0], q[1], q[2], q[3], q[4], q[5], q[6]};
      CHECK(field->value(Vec3(p[0], p[1], p[2])) == Approx(in->evaluate(all)).margin(1e-12));
    }
  }
}

TEST_CASE("sdl function: an isosurface's text inlines user functions", "[sdl][function]") {
  const Value v =
      valueAfter(kFunctions +
                     "#declare K = 0.5;\n#declare G = function(a, b) { a*b - K }\n"
                     "#declare F = function { G(x, select(y, 1, z)) + f_sphere(x, y, z, 2) }\n",
                 "F");
  REQUIRE(v.type == ValueType::Function);
  CHECK(functionText(*v.function, {"x", "y", "(-z)"}) ==
        "((((x * (y < 0 ? 1 : (-z))) - 0.5)) + (f_sphere(x, y, (-z), 2)))");
}

TEST_CASE("sdl function: errors are located inside the function's text", "[sdl][function]") {
  using sdltest::errorOf;
  CHECK(errorOf("#declare G = function(a, b) { a }\n#declare F = function { 1 + G(x) }\n")
            .rfind("test.pov:2:29: error: 'G' takes 2 arguments, 1 given", 0) == 0);
  CHECK(errorOf("#declare F = function { x + foo }\n")
            .rfind("test.pov:1:29: error: 'foo' is neither a parameter of the function nor a "
                   "declared float",
                   0) == 0);
  CHECK(errorOf("#declare F = function { x + bar(y) }\n")
            .rfind("test.pov:1:29: error: unknown function 'bar'", 0) == 0);
  CHECK(errorOf("#declare F = function { sin(x, y) }\n")
            .rfind("test.pov:1:25: error: 'sin' takes 1 argument, 2 given", 0) == 0);
  CHECK(errorOf("#declare F = function { x^2 }\n")
            .rfind("test.pov:1:26: error: expected an operator or the '}' closing the function",
                   0) == 0);
  CHECK(errorOf("#declare F = function { x/0 }\n")
            .rfind("test.pov:1:26: error: division by zero", 0) == 0);
  CHECK(errorOf("#declare V = <1, 2, 3>;\n#declare F = function { x*V }\n")
            .rfind("test.pov:2:27: error: a function can use float identifiers, not the vector "
                   "identifier 'V'",
                   0) == 0);
  CHECK(errorOf("#declare F = function { x }\n#declare F = function { F(x, y, z) }\n")
            .rfind("test.pov:2:25: error: recursive function calls are not allowed", 0) == 0);
  // Calls in expressions: the arity, and what Lucent cannot evaluate, at the call.
  CHECK(errorOf("#declare F = function(a) { a }\n#declare R = F(1, 2);\n")
            .rfind("test.pov:2:14: error: 'F' takes 1 argument, 2 given", 0) == 0);
  const std::string pigment =
      errorOf("#declare P = function { pigment { rgb 1 } }\n#declare R = 1 + P(1, 2, 3);\n");
  CHECK(pigment.rfind("test.pov:2:18: error: cannot evaluate 'P': it is a pigment function", 0) ==
        0);
  CHECK(pigment.find("test.pov:1:14: note:") != std::string::npos);
  const std::string noise = errorOf(kFunctions +
                                    "#declare F = function { 1 + f_noise3d(x, y, z) }\n"
                                    "#declare R = F(1, 2, 3);\n");
  // (The language core alone: with a scene reader, f_noise3d is a pattern function.)
  CHECK(noise.rfind("test.pov:4:14: error: 'f_noise3d' (internal(76)) is a noise function", 0) ==
        0);
  CHECK(noise.find("test.pov:3:29: note: the cause, in the function's declaration") !=
        std::string::npos);
}

TEST_CASE("sdl function: nesting and evaluation are bounded", "[sdl][function]") {
  // Each function doubles the work of the one before: 2^40 steps are refused, not done.
  std::string text = "#declare F0 = function { x + 1 }\n";
  for (int i = 1; i <= 40; ++i)
    text += "#declare F" + std::to_string(i) + " = function { F" + std::to_string(i - 1) +
            "(x, y, z) + F" + std::to_string(i - 1) + "(x, y, z) }\n";
  text += "#declare R = F40(1, 2, 3);\n";
  CHECK(sdltest::errorOf(text).find("takes more than 10000000 steps") != std::string::npos);
  // pow(a, 8) is a's square squared twice, a shared node: eight of them within each other
  // would evaluate `x` 8^8 times and write it out as many times; both are refused at once.
  const std::string powers =
      "#declare F = function { pow(pow(pow(pow(pow(pow(pow(pow(x, 8), 8), 8), 8), 8), 8), 8), 8) "
      "}\n";
  CHECK(sdltest::errorOf(powers + "#declare R = F(1, 2, 3);\n").find("takes more than") !=
        std::string::npos);
  const Value f = valueAfter(powers, "F");
  REQUIRE(f.type == ValueType::Function);
  CHECK_THROWS_WITH(functionText(*f.function, {"x", "y", "z"}),
                    Catch::Contains("longer than 1000000 characters"));
  // A chain of calls deeper than the bound is refused where it is declared.
  std::string deep = "#declare F0 = function { x }\n";
  for (int i = 1; i <= 600; ++i)
    deep += "#declare F" + std::to_string(i) + " = function { F" + std::to_string(i - 1) +
            "(x, y, z) }\n";
  CHECK(sdltest::errorOf(deep).find("nested more than 1000 deep") != std::string::npos);
}
