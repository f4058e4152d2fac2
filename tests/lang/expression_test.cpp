// Expressions in ${...}: every operator's precedence and associativity, every function
// against std:: or a value worked out by hand, the shortest round-trip formatting, and
// random(seed, i): pinned values, its range, what it depends on and a distribution test.
// Most cases go through Parameters::substitute (as every attribute does); a few through a
// real scene attribute, to show the parser hands the attribute to the same evaluator.
#include "lang/expression.h"
#include "lang/expression_functions.h"
#include "lang/parameters.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

using namespace lucent;

namespace {

// The text `text` becomes, or "error: MESSAGE @OFFSET" when substitution fails. Names come
// from -D style defines (taken literally) and the built-ins.
std::string sub(const std::string& text, const std::map<std::string, std::string>& defines = {}) {
  Diagnostics diags;
  Parameters params(defines, diags);
  SubstitutionError error;
  std::optional<std::string> out = params.substitute(text, nullptr, error);
  if (out) return *out;
  return "error: " + error.message + " @" + std::to_string(error.offset);
}

// The value of one expression, read back from its text exactly.
double eval(const std::string& expr, const std::map<std::string, std::string>& defines = {}) {
  std::string text = sub("${" + expr + "}", defines);
  INFO("${" << expr << "} gave '" << text << "'");
  double v = std::numeric_limits<double>::quiet_NaN();
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  REQUIRE(ec == std::errc());
  REQUIRE(end == text.data() + text.size());
  return v;
}

// Exactly equal, or within a few ulps of a hand-derived value that is itself rounded.
bool near(double a, double b, double tol = 1e-15) {
  return std::abs(a - b) <= tol * std::max(1.0, std::abs(b));
}

double floored(double a, double b) {
  return a - b * std::floor(a / b);
}  // independent of the implementation

}  // namespace

TEST_CASE("expressions: ?: is the lowest operator and nests to the right", "[lang][expression]") {
  CHECK(eval("1 ? 2 : 3") == 2);
  CHECK(eval("0 ? 2 : 3") == 3);
  CHECK(eval("0 || 1 ? 5 : 6") == 5);   // (0 || 1) ? 5 : 6
  CHECK(eval("0 ? 2 : 3 + 10") == 13);  // 0 ? 2 : (3 + 10)
  CHECK(eval("1 ? 2 : 3 + 10") == 2);
  CHECK(eval("0 ? 1 : 0 ? 2 : 3") == 3);  // 0 ? 1 : (0 ? 2 : 3)
  CHECK(eval("1 ? 0 ? 4 : 5 : 6") == 5);  // a ?: in the middle branch
  CHECK(eval("2 > 1 ? 10 : 20") == 10);
}

TEST_CASE("expressions: || below &&, && below ==, == below <, < below +, + below *",
          "[lang][expression]") {
  CHECK(eval("1 || 0 && 0") == 1);  // 1 || (0 && 0); (1 || 0) && 0 would be 0
  CHECK(eval("0 && 0 || 1") == 1);
  CHECK(eval("1 && 2 == 2") == 1);  // 1 && (2 == 2); (1 && 2) == 2 would be 0
  CHECK(eval("2 == 2 < 3") == 0);   // 2 == (2 < 3) = 2 == 1; (2 == 2) < 3 would be 1
  CHECK(eval("3 != 2 > 1") == 1);   // 3 != (2 > 1)
  CHECK(eval("3 < 1 + 5") == 1);    // 3 < 6; (3 < 1) + 5 would be 5
  CHECK(eval("1 + 2 >= 3") == 1);
  CHECK(eval("2 + 3 * 4") == 14);
  CHECK(eval("2 * 3 + 4") == 10);
  CHECK(eval("1 + 7 % 4") == 4);  // % binds like *
  CHECK(eval("1 + 8 / 4") == 3);
}

TEST_CASE("expressions: unary - and ! bind tighter than * and looser than ^",
          "[lang][expression]") {
  CHECK(eval("!0 * 2") == 2);  // (!0) * 2; !(0 * 2) would be 1
  CHECK(eval("!0 + 1") == 2);
  CHECK(eval("-2 * 3") == -6);
  CHECK(eval("-2 ^ 2") == -4);  // -(2 ^ 2)
  CHECK(eval("(-2) ^ 2") == 4);
  CHECK(eval("2 ^ -1") == 0.5);
  CHECK(eval("-(-3)") == 3);
  CHECK(eval("!(!5)") == 1);
  CHECK(eval("-(!0)") == -1);
  CHECK(eval("-3 + 5") == 2);
  CHECK(eval("2 - -3") == 5);
}

// muParser refuses an infix operator right after another, so runs of up to four are
// defined as operators of their own (expression_functions.cpp): they must compose exactly.
TEST_CASE("expressions: unary operators stack: --x, !!x, -!x, !-x", "[lang][expression]") {
  CHECK(sub("${--3}") == "3");
  CHECK(sub("${!!5}") == "1");
  CHECK(sub("${-!0}") == "-1");
  CHECK(sub("${!-1}") == "0");
  CHECK(sub("${!!!0}") == "1");
  CHECK(sub("${-!-!0}") == "-0");  // !0 = 1, then -1, !-1 = 0, -0
  CHECK(eval("--2^2") == 4);       // the run still binds below ^: -(-(2^2))
  CHECK(eval("2---3") == -1);      // binary minus, then the run --
  CHECK(eval("1 - -1") == 2);
}

TEST_CASE("expressions: ^ is right-associative, the others left-associative",
          "[lang][expression]") {
  CHECK(eval("2 ^ 3 ^ 2") == 512);  // 2 ^ 9; (2 ^ 3) ^ 2 would be 64
  CHECK(eval("10 - 4 - 3") == 3);
  CHECK(eval("64 / 4 / 2") == 8);
  CHECK(eval("17 % 10 % 4") == 3);  // (17 % 10) % 4; 17 % (10 % 4) would be 1
  CHECK(eval("2 * 3 % 4") == 2);    // (2 * 3) % 4; 2 * (3 % 4) would be 6
  CHECK(eval("1 < 2 < 3") == 1);    // (1 < 2) < 3
  CHECK(eval("3 > 2 > 1") == 0);    // (3 > 2) > 1 = 1 > 1
}

TEST_CASE("expressions: parentheses override precedence", "[lang][expression]") {
  CHECK(eval("(2 + 3) * 4") == 20);
  CHECK(eval("2 ^ (3 - 1)") == 4);
  CHECK(eval("(1 ? 2 : 3) + 1") == 3);
  CHECK(eval("((((7))))") == 7);
  CHECK(eval("-(2 + 3)") == -5);
  CHECK(eval("!(1 - 1)") == 1);
}

TEST_CASE("expressions: comparisons and logic give exactly 1 or 0", "[lang][expression]") {
  CHECK(sub("${3 < 4}") == "1");
  CHECK(sub("${4 < 3}") == "0");
  CHECK(sub("${3 <= 3}") == "1");
  CHECK(sub("${3.5 <= 3}") == "0");
  CHECK(sub("${4 > 3}") == "1");
  CHECK(sub("${3 > 3}") == "0");
  CHECK(sub("${3 >= 3}") == "1");
  CHECK(sub("${2 >= 3}") == "0");
  CHECK(sub("${0.5 == 0.5}") == "1");
  CHECK(sub("${0.1 + 0.2 == 0.3}") == "0");  // exact comparison of doubles
  CHECK(sub("${2 != 3}") == "1");
  CHECK(sub("${2 != 2}") == "0");
  CHECK(sub("${2 && 3}") == "1");  // not 3
  CHECK(sub("${2 && 0}") == "0");
  CHECK(sub("${0 || 5}") == "1");  // not 5
  CHECK(sub("${0 || 0}") == "0");
  CHECK(sub("${!5}") == "0");
  CHECK(sub("${!0}") == "1");
  CHECK(sub("${-0.5 && 1}") == "1");  // any non-zero is true
}

TEST_CASE("expressions: % is a floored modulo, with the sign of the divisor",
          "[lang][expression]") {
  CHECK(eval("5 % 3") == 2);
  CHECK(eval("-1 % 3") == 2);
  CHECK(eval("1 % -3") == -2);
  CHECK(eval("-7 % -3") == -1);
  CHECK(eval("7.5 % 2") == 1.5);
  CHECK(eval("-7.5 % 2") == 0.5);
  CHECK(eval("6 % 3") == 0);
  CHECK(eval("-6 % 3") == 0);
  for (double a : {-9.0, -4.0, -0.25, 0.0, 3.0, 11.0, 12.75})
    for (double b : {-4.0, -1.5, 2.0, 5.0}) {
      INFO(a << " % " << b);
      CHECK(flooredModulo(a, b) == floored(a, b));
      CHECK(eval(formatNumber(a) + " % " + formatNumber(b)) == floored(a, b));
    }
}

TEST_CASE("expressions: the trigonometric functions work in radians", "[lang][expression]") {
  for (double x : {-2.0, -0.3, 0.0, 0.5, 1.0, 2.5}) {
    const std::string s = formatNumber(x);
    INFO("x = " << s);
    CHECK(eval("sin(" + s + ")") == std::sin(x));
    CHECK(eval("cos(" + s + ")") == std::cos(x));
    CHECK(eval("tan(" + s + ")") == std::tan(x));
    CHECK(eval("atan(" + s + ")") == std::atan(x));
  }
  for (double x : {-1.0, -0.5, 0.0, 0.25, 1.0}) {
    const std::string s = formatNumber(x);
    CHECK(eval("asin(" + s + ")") == std::asin(x));
    CHECK(eval("acos(" + s + ")") == std::acos(x));
  }
  // By hand: the familiar angles.
  CHECK(near(eval("sin(pi / 6)"), 0.5));
  CHECK(near(eval("cos(pi / 3)"), 0.5));
  CHECK(near(eval("tan(pi / 4)"), 1.0));
  CHECK(near(eval("asin(1)"), M_PI / 2));
  CHECK(near(eval("acos(-1)"), M_PI));
  CHECK(near(eval("atan(1)"), M_PI / 4));
  CHECK(eval("sin(0)") == 0);
  CHECK(eval("cos(0)") == 1);
}

TEST_CASE("expressions: atan2 takes y first, then x, and covers the four quadrants",
          "[lang][expression]") {
  CHECK(near(eval("atan2(1, 1)"), M_PI / 4));
  CHECK(near(eval("atan2(1, -1)"), 3 * M_PI / 4));
  CHECK(near(eval("atan2(-1, -1)"), -3 * M_PI / 4));
  CHECK(near(eval("atan2(-1, 1)"), -M_PI / 4));
  CHECK(near(eval("atan2(1, 0)"), M_PI / 2));
  CHECK(eval("atan2(0, 1)") == 0);
  CHECK(eval("atan2(3, -4)") == std::atan2(3.0, -4.0));
}

TEST_CASE("expressions: sqrt, exp and the logarithms", "[lang][expression]") {
  CHECK(eval("sqrt(16)") == 4);
  CHECK(eval("sqrt(2)") == std::sqrt(2.0));
  CHECK(eval("sqrt(0)") == 0);
  CHECK(eval("exp(0)") == 1);
  CHECK(eval("exp(1)") == std::exp(1.0));
  CHECK(near(eval("exp(1)"), M_E));
  CHECK(eval("exp(-2.5)") == std::exp(-2.5));
  CHECK(eval("ln(1)") == 0);
  CHECK(near(eval("ln(e)"), 1.0));
  CHECK(eval("ln(10)") == std::log(10.0));
  CHECK(eval("log10(1000)") == 3);
  CHECK(eval("log10(0.01)") == -2);
  CHECK(eval("log10(7)") == std::log10(7.0));
  CHECK(eval("log2(8)") == 3);
  CHECK(eval("log2(0.125)") == -3);
  CHECK(eval("log2(10)") == std::log2(10.0));
}

TEST_CASE("expressions: abs, sign, floor, ceil, round (halves away from zero) and trunc",
          "[lang][expression]") {
  CHECK(eval("abs(-3.5)") == 3.5);
  CHECK(eval("abs(2)") == 2);
  CHECK(eval("abs(0)") == 0);
  CHECK(eval("sign(-3)") == -1);
  CHECK(eval("sign(0)") == 0);
  CHECK(eval("sign(0.001)") == 1);
  CHECK(eval("floor(2.7)") == 2);
  CHECK(eval("floor(-2.5)") == -3);
  CHECK(eval("floor(3)") == 3);
  CHECK(eval("ceil(2.1)") == 3);
  CHECK(eval("ceil(-2.5)") == -2);
  CHECK(eval("round(2.5)") == 3);
  CHECK(eval("round(-2.5)") == -3);
  CHECK(eval("round(0.5)") == 1);
  CHECK(eval("round(2.4999)") == 2);
  CHECK(eval("round(-0.4)") == 0);
  CHECK(eval("trunc(2.7)") == 2);
  CHECK(eval("trunc(-2.7)") == -2);
}

TEST_CASE("expressions: pow, min, max, clamp, mix, radians and degrees", "[lang][expression]") {
  CHECK(eval("pow(2, 10)") == 1024);
  CHECK(eval("pow(9, 0.5)") == 3);
  CHECK(eval("pow(2, -2)") == 0.25);
  CHECK(eval("pow(1.5, 2.5)") == std::pow(1.5, 2.5));
  CHECK(eval("pow(2, 3) == 2 ^ 3") == 1);
  CHECK(eval("min(3, 1, 2)") == 1);
  CHECK(eval("min(5)") == 5);
  CHECK(eval("min(-1, -7)") == -7);
  CHECK(eval("max(3, 1, 2)") == 3);
  CHECK(eval("max(4, 9, -2, 8, 1)") == 9);
  CHECK(eval("max(5)") == 5);
  CHECK(eval("clamp(5, 0, 1)") == 1);
  CHECK(eval("clamp(-1, 0, 1)") == 0);
  CHECK(eval("clamp(0.5, 0, 1)") == 0.5);
  CHECK(eval("mix(2, 4, 0.25)") == 2.5);  // 2 + (4 - 2) * 0.25
  CHECK(eval("mix(2, 4, 0)") == 2);
  CHECK(eval("mix(2, 4, 1)") == 4);
  CHECK(eval("mix(10, 0, 0.5)") == 5);
  CHECK(eval("mix(0, 1, 2)") == 2);  // no clamping of t
  CHECK(near(eval("radians(180)"), M_PI));
  CHECK(near(eval("radians(90)"), M_PI / 2));
  CHECK(near(eval("degrees(pi)"), 180));
  CHECK(near(eval("degrees(1)"), 180 / M_PI));
  CHECK(near(eval("degrees(radians(37))"), 37, 1e-14));
}

TEST_CASE("expressions: pi and e are the constants, names in expressions read their values",
          "[lang][expression]") {
  CHECK(eval("pi") == M_PI);
  CHECK(eval("e") == M_E);
  CHECK(eval("2 * pi") == 2 * M_PI);
  CHECK(eval("r * 2", {{"r", "1.25"}}) == 2.5);
  CHECK(eval("a + b * c", {{"a", "1"}, {"b", "2"}, {"c", "3"}}) == 7);
  CHECK(eval("cos(a)", {{"a", "0.75"}}) == std::cos(0.75));
  CHECK(eval("clock + frame + frames") == 2);  // 0 + 1 + 1 without <animation>
}

TEST_CASE("expressions: results are written in the shortest form that reads back exactly",
          "[lang][expression]") {
  CHECK(sub("${0.1+0.2}") == "0.30000000000000004");
  CHECK(sub("${2*3}") == "6");
  CHECK(sub("${1/3}") == "0.3333333333333333");
  CHECK(sub("${1/4}") == "0.25");
  CHECK(sub("${-1/8}") == "-0.125");
  CHECK(sub("${10/2}") == "5");
  CHECK(sub("${1e3}") == "1000");
  CHECK(sub("${0 * -1}") == "-0");
  CHECK(sub("${2^0.5}") == "1.4142135623730951");
  CHECK(sub("${4*cos(0)} 2 ${4*sin(0)}") == "4 2 0");
  CHECK(sub("rotate-y(${360*0.25})") == "rotate-y(90)");
  CHECK(sub("a$$b") == "a$b");        // $$ is a literal '$'
  CHECK(sub("$${1+1}") == "${1+1}");  // ... even before a brace
  CHECK(sub("$$${1+1}") == "$2");
  // Every result reads back as the very same double.
  for (const char* e :
       {"1/3", "2/7", "pi", "e^10", "1e-300*3", "sqrt(2)", "1e22/3", "-123456789.125/1024"}) {
    std::string text = sub(std::string("${") + e + "}");
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    INFO(e << " -> " << text);
    CHECK(back == eval(e));
    CHECK(text.size() <= 24);  // at most 17 significant digits, a sign, a point and an exponent
  }
}

TEST_CASE("expressions: an expression in a real attribute gives the attribute its value",
          "[lang][expression]") {
  const std::string xml = R"(<scene version="1">
  <camera/>
  <param name="r" value="2"/>
  <sphere center="${4*cos(pi/3)} ${r ^ 3 % 5} ${r &lt; 3 &amp;&amp; r &gt; 1 ? 7 : 9}" radius="${0.5*r}"/>
  <sphere radius="${random(42, 7) + 1}"/>
</scene>)";
  ParseResult r = parseSceneString(xml, "expr.xml");
  REQUIRE(r.scene);
  const auto& kids = r.scene->root->children;
  REQUIRE(kids.size() == 2);
  const auto& a = std::get<SphereSpec>(*kids[0]->shape);
  CHECK(a.radius == 1.0);
  CHECK(near(a.center.x, 2.0));
  CHECK(a.center.x == 4 * std::cos(M_PI / 3));
  CHECK(a.center.y == 3);  // 8 % 5
  CHECK(a.center.z == 7);
  CHECK(std::get<SphereSpec>(*kids[1]->shape).radius == sceneRandom(42, 7) + 1);
}

TEST_CASE("expressions: a parameter is read after its own substitution, and hides a built-in name",
          "[lang][expression]") {
  const std::string xml = R"(<scene version="1">
  <camera/>
  <param name="a" value="${2 * 3}"/>
  <param name="b" value="$a"/>
  <param name="e" value="5"/>
  <sphere center="${a + 1} ${b / 4} ${e * 2}" radius="${pi / pi}"/>
</scene>)";
  ParseResult r = parseSceneString(xml, "names.xml");
  REQUIRE(r.scene);
  const auto& s = std::get<SphereSpec>(*r.scene->root->children.at(0)->shape);
  CHECK(s.center.x == 7);
  CHECK(s.center.y == 1.5);
  CHECK(s.center.z == 10);  // the scene's e, not 2.718...
  CHECK(s.radius == 1);
}

// random(seed, i): pinned values, so that a change of hash, compiler or machine is caught.
TEST_CASE("expressions: random(seed, i) gives the same pinned values on every build",
          "[lang][expression][random]") {
  // Worked out once by a separate copy of the hash (SplitMix64's finaliser over the two
  // arguments' IEEE-754 bits, 53 bits of the result), written as exact hexadecimal floats.
  CHECK(sceneRandom(0, 0) == 0x1.094db8bb4b47p-4);       // 0.064771386726265368
  CHECK(sceneRandom(0, 1) == 0x1.48213c746a904p-3);      // 0.16021964292787783
  CHECK(sceneRandom(1, 0) == 0x1.37dda92c15ed5p-1);      // 0.60911301291613518
  CHECK(sceneRandom(42, 7) == 0x1.bb9686c13ec81p-1);     // 0.86638280018759428
  CHECK(sceneRandom(-3.5, 1e6) == 0x1.f6d3b6c253dcp-5);  // 0.061380249930717223
  CHECK(sub("${random(42, 7)}") == "0.8663828001875943");
  CHECK(sub("${random(0, 1)}") == "0.16021964292787783");
  // The same call twice, and in one expression twice, agree.
  CHECK(eval("random(5, 9) - random(5, 9)") == 0);
  CHECK(sub("${random(5, 9)}") == sub("${random(5, 9)}"));
}

TEST_CASE("expressions: random(seed, i) depends on both arguments and only on their values",
          "[lang][expression][random]") {
  CHECK(sceneRandom(1, 2) != sceneRandom(2, 1));
  CHECK(sceneRandom(0, 0) != sceneRandom(0, 1));
  CHECK(sceneRandom(0, 0) != sceneRandom(1, 0));
  CHECK(sceneRandom(0, 0.5) != sceneRandom(0, 0));  // fractional arguments count too
  CHECK(sceneRandom(0.5, 0) != sceneRandom(0, 0));
  CHECK(sceneRandom(-0.0, 3) == sceneRandom(0.0, 3));  // -0 is the number 0
  CHECK(sceneRandom(3, -0.0) == sceneRandom(3, 0.0));
  CHECK(eval("random(2 - 1, 1 + 1)") == sceneRandom(1, 2));  // only the values count
  // Over many pairs, changing either argument changes the value.
  int sameSeed = 0, sameIndex = 0;
  for (int s = 0; s < 100; ++s)
    for (int i = 0; i < 100; ++i) {
      if (sceneRandom(s, i) == sceneRandom(s, i + 1)) ++sameIndex;
      if (sceneRandom(s, i) == sceneRandom(s + 1, i)) ++sameSeed;
    }
  CHECK(sameSeed == 0);
  CHECK(sameIndex == 0);
}

namespace {

struct Sample {
  double min = 1, max = 0, mean = 0, variance = 0, chiSquare = 0, lag1 = 0;
};

// 10^6 draws of `draw(k)`: range, mean, variance, a 100-bin chi-square and the correlation of
// neighbours.
template <class F>
Sample sample(F draw) {
  const int n = 1'000'000, bins = 100;
  std::vector<int> count(bins, 0);
  std::vector<double> x(n);
  Sample s;
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    x[k] = draw(k);
    s.min = std::min(s.min, x[k]);
    s.max = std::max(s.max, x[k]);
    sum += x[k];
    int b = static_cast<int>(x[k] * bins);
    if (b >= 0 && b < bins) ++count[b];
  }
  s.mean = sum / n;
  double sq = 0, cross = 0;
  for (int k = 0; k < n; ++k) {
    sq += (x[k] - s.mean) * (x[k] - s.mean);
    if (k + 1 < n) cross += (x[k] - s.mean) * (x[k + 1] - s.mean);
  }
  s.variance = sq / (n - 1);
  s.lag1 = cross / sq;
  const double expected = static_cast<double>(n) / bins;
  for (int c : count) s.chiSquare += (c - expected) * (c - expected) / expected;
  return s;
}

// For 10^6 independent uniform draws (the thresholds are fixed, the draws deterministic:
// the test passes or fails the same way every time):
// - the chi-square over 100 equal bins has 99 degrees of freedom; by the Wilson-Hilferty
//   approximation its 10^-6 lower and upper quantiles are 45.6 and 181.1, so a uniform
//   generator falls outside [45, 182] with probability about 2e-6. Below 45 is too even to
//   be random (a lattice such as frac(k * golden ratio)), above 182 is not uniform.
// - the mean's standard deviation is sqrt(1/12 / 10^6) = 2.89e-4: |mean - 1/2| < 1.6e-3 is
//   5.5 of them.
// - the variance's standard deviation is sqrt((1/80 - 1/144) / 10^6) = 7.45e-5 (the fourth
//   central moment of U(0,1) is 1/80): |variance - 1/12| < 4.1e-4 is 5.5 of them.
// - the lag-1 correlation's standard deviation is 1/sqrt(10^6) = 1e-3: |r| < 5.5e-3.
void checkUniform(const Sample& s) {
  INFO("min " << s.min << " max " << s.max << " mean " << s.mean << " variance " << s.variance
              << " chi2 " << s.chiSquare << " lag1 " << s.lag1);
  CHECK(s.min >= 0.0);
  CHECK(s.max < 1.0);
  CHECK(std::abs(s.mean - 0.5) < 1.6e-3);
  CHECK(std::abs(s.variance - 1.0 / 12.0) < 4.1e-4);
  CHECK(s.chiSquare > 45.0);
  CHECK(s.chiSquare < 182.0);
  CHECK(std::abs(s.lag1) < 5.5e-3);
}

}  // namespace

TEST_CASE("expressions: random(seed, i) over 10^6 indices is uniform between 0 and 1",
          "[lang][expression][random]") {
  checkUniform(sample([](int k) { return sceneRandom(7, k); }));
}

TEST_CASE("expressions: random(seed, i) over 10^6 seeds is uniform between 0 and 1",
          "[lang][expression][random]") {
  checkUniform(sample([](int k) { return sceneRandom(k, 3); }));
}

TEST_CASE("expressions: the check above would catch a lattice and a biased generator",
          "[lang][expression][random]") {
  // The thresholds of checkUniform are not vacuous: a perfectly even sequence fails the
  // chi-square from below, a slightly skewed one from above.
  Sample lattice = sample([](int k) { return std::fmod(k * 0.6180339887498949, 1.0); });
  CHECK(lattice.chiSquare < 45.0);
  Sample skewed = sample([](int k) { return std::pow(sceneRandom(7, k), 1.02); });
  CHECK(skewed.chiSquare > 182.0);
}

TEST_CASE("expressions: POV-Ray's functions.inc functions, by name, at POV-Ray's values",
          "[lang][expression]") {
  // f_sphere: |p| - r; f_torus: the distance to the ring less the minor radius;
  // f_rounded_box: the distance to the box shrunk by r, less r (and POV-Ray's 1e-6).
  CHECK(near(eval("f_sphere(3, 4, 0, 2)"), 3.0));
  CHECK(near(eval("f_torus(3, 0, 0, 2, 0.5)"), 0.5));
  CHECK(near(eval("f_rounded_box(2, 0, 0, 0.1, 1, 1, 1)"), (2.0 - 0.9) - 0.1 - 1e-6));
  CHECK(near(eval("f_r(1, 2, 2)"), 3.0));
  // The wrong number of arguments, a misspelt name and a name used as a value.
  CHECK(sub("${f_sphere(1, 2, 3)}").rfind("error: ", 0) == 0);
  CHECK(sub("${f_spher(1, 2, 3, 4)}").find("did you mean 'f_sphere'") != std::string::npos);
  CHECK(sub("${f_sphere + 1}").find("'f_sphere' is a function") != std::string::npos);
}
