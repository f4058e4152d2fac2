// The value syntax: numbers, lists, vectors, colours (#rrggbb through the exact sRGB
// curve), booleans, integers; and the did-you-mean distance.
#include "lang/values.h"
#include "lang/color_names.h"
#include "lang/did_you_mean.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace lucent;

TEST_CASE("lang: numbers are decimal floats without junk, inf only where allowed",
          "[lang][values]") {
  CHECK(*parseNumber("1") == 1.0);
  CHECK(*parseNumber("-2.5") == -2.5);
  CHECK(*parseNumber("1e-3") == 1e-3);
  CHECK(*parseNumber(".5") == 0.5);
  CHECK(*parseNumber("+4") == 4.0);
  CHECK(*parseNumber("  7  ") == 7.0);
  CHECK(parseNumber("1.5x").error == "expected a number, got '1.5x'");
  CHECK(parseNumber("").error == "expected a number, got ''");
  CHECK(parseNumber("0x10").error == "expected a number, got '0x10'");
  CHECK(parseNumber("1 2").error == "expected a number, got '1 2'");
  CHECK(parseNumber("++1").error == "expected a number, got '++1'");
  CHECK(parseNumber("nan").error == "expected a number, got 'nan' (NaN is not allowed)");
  CHECK_THAT(parseNumber("inf").error, Catch::StartsWith("expected a finite number, got 'inf'"));
  CHECK_THAT(parseNumber("1e999").error, Catch::Contains("out of the range"));
  CHECK(*parseNumber("inf", true) == kInf);
  CHECK(*parseNumber("+inf", true) == kInf);
  CHECK(*parseNumber("infinity", true) == kInf);
  CHECK_FALSE(parseNumber("nan", true));
}

TEST_CASE("lang: vectors are three numbers separated by spaces and/or a comma", "[lang][values]") {
  CHECK(*parseVector("0 1 0") == Vec3(0, 1, 0));
  CHECK(*parseVector("0,1,0") == Vec3(0, 1, 0));
  CHECK(*parseVector(" 0 , 1 ,\t0 ") == Vec3(0, 1, 0));
  CHECK(parseVector("1 2").error == "expected 3 numbers, got 2 ('1 2')");
  CHECK(parseVector("1 2 3 4").error == "expected 3 numbers, got 4 ('1 2 3 4')");
  CHECK(parseVector("1,,2,3").error == "two ',' without a value between them in '1,,2,3'");
  CHECK(parseVector(",1 2 3").error == "unexpected ',' before the first value in ',1 2 3'");
  CHECK(parseVector("1 2 3,").error == "unexpected ',' after the last value in '1 2 3,'");
  CHECK(parseVector("1 2 inf").error ==
        "expected a finite number, got 'inf' (inf is allowed only for distances that may be "
        "infinite)");
}

TEST_CASE("lang: #rrggbb colours are decoded to linear with the exact sRGB curve",
          "[lang][values]") {
  auto hex = [](const char* t) {
    auto c = parseColor(t);
    REQUIRE(c);
    CHECK_FALSE(c->scalar);
    return c->color;
  };
  CHECK(hex("#000000") == Color(0.0f));
  CHECK(hex("#ffffff") == Color(1.0f));
  CHECK(hex("#FFFFFF") == Color(1.0f));
  // 10/255 = 0.0392 is on the linear segment (<= 0.04045): c / 12.92.
  CHECK(hex("#0a0a0a").r == static_cast<float>(0.003035269835488375));
  // 11/255 = 0.0431 is on the power segment: ((c + 0.055) / 1.055)^2.4.
  CHECK(hex("#0b0b0b").g == static_cast<float>(0.003346535763899161));
  Color c = hex("#80cc33");
  CHECK(c.r == static_cast<float>(0.21586050011389926));
  CHECK(c.g == static_cast<float>(0.6038273388553378));
  CHECK(c.b == static_cast<float>(0.033104766570885055));
  CHECK(srgbToLinear(0.5) == std::pow((0.5 + 0.055) / 1.055, 2.4));

  CHECK(parseColor("#12345").error == "expected #rrggbb (six hexadecimal digits), got '#12345'");
  CHECK(parseColor("#12345g").error == "expected #rrggbb (six hexadecimal digits), got '#12345g'");
  CHECK(parseColor("#fff").error == "expected #rrggbb (six hexadecimal digits), got '#fff'");
}

TEST_CASE("lang: colours of three numbers are linear, one number is grey", "[lang][values]") {
  auto rgb = parseColor("1 0.5 0");
  REQUIRE(rgb);
  CHECK(rgb->color == Color(1.0f, 0.5f, 0.0f));
  CHECK_FALSE(rgb->scalar);
  auto grey = parseColor("0.5");
  REQUIRE(grey);
  CHECK(grey->color == Color(0.5f));
  CHECK(grey->scalar);
  CHECK(parseColor("1 0").error ==
        "expected a colour (3 numbers, 1 number for grey, #rrggbb or a CSS colour name), got 2 "
        "numbers ('1 0')");
  // Beyond float range, and beyond the 1e30 limit of every number (docs/security.md).
  CHECK(parseColor("1e39").error ==
        "the number '1e39' is too large (the limit is 1e30 in magnitude)");
}

TEST_CASE("lang: CSS colour names are sRGB like #rrggbb, in any case", "[lang][values]") {
  auto css = parseColor("midnightblue");  // #191970
  REQUIRE(css);
  CHECK(css->color == parseColor("#191970")->color);
  CHECK_FALSE(css->scalar);
  CHECK(parseColor(" MidnightBlue ")->color == css->color);
  CHECK(parseColor("red")->color == Color(1.0f, 0.0f, 0.0f));
  // CSS, not X11, where the two disagree: CSS green is #008000, gray #808080.
  CHECK(parseColor("green")->color == parseColor("#008000")->color);
  CHECK(parseColor("grey")->color == parseColor("#808080")->color);
  CHECK(parseColor("gray")->color == parseColor("#808080")->color);
  CHECK(parseColor("rebeccapurple")->color == parseColor("#663399")->color);
  CHECK(parseColor("#ffffff")->color == parseColor("white")->color);
  CHECK(cssColorNames().size() == 148);
  CHECK(std::is_sorted(cssColorNames().begin(), cssColorNames().end()));
  for (std::string_view name : cssColorNames()) CHECK(cssColorByName(name));

  CHECK(parseColor("redd").error ==
        "unknown colour name 'redd' (did you mean 'red'?); a colour is 3 numbers, 1 number "
        "for grey, #rrggbb or a CSS colour name");
  CHECK(parseColor("midnigthblue").error.find("(did you mean 'midnightblue'?)") !=
        std::string::npos);
  CHECK(parseColor("xyzzyq").error ==
        "unknown colour name 'xyzzyq'; a colour is 3 numbers, 1 number for grey, #rrggbb or a "
        "CSS colour name");
  CHECK(parseColor("nan").error == "expected a number, got 'nan' (NaN is not allowed)");
  // A word followed by numbers is not a name.
  CHECK(parseColor("red 1").error == "expected a number, got 'red'");
}

TEST_CASE("lang: integers, booleans", "[lang][values]") {
  CHECK(*parseInteger("640") == 640);
  CHECK(*parseInteger(" +3 ") == 3);
  CHECK(parseInteger("640.0").error == "expected a whole number, got '640.0'");
  CHECK(parseInteger("1e3").error == "expected a whole number, got '1e3'");
  CHECK(parseInteger("99999999999999999999").error ==
        "the number '99999999999999999999' is too large");
  CHECK(*parseIntegerList("0 1, 2") == std::vector<long long>{0, 1, 2});
  CHECK(*parseBool("true"));
  CHECK_FALSE(*parseBool(" false "));
  CHECK(parseBool("yes").error == "expected true or false, got 'yes'");
  CHECK(parseBool("1").error == "expected true or false, got '1'");
}

TEST_CASE("lang: did you mean: the closest name within a small edit distance", "[lang][values]") {
  CHECK(editDistance("radus", "radius") == 1);
  CHECK(editDistance("kitten", "sitting") == 3);
  CHECK(editDistance("Sphere", "sphere") == 0);  // case-insensitive
  std::vector<std::string_view> attrs{"center", "radius", "id", "transform", "material"};
  CHECK(didYouMean("radus", attrs) == " (did you mean 'radius'?)");
  CHECK(didYouMean("Radius", attrs) == " (did you mean 'radius'?)");
  CHECK(didYouMean("centre", attrs) == " (did you mean 'center'?)");
  CHECK(didYouMean("transfrom", attrs) == " (did you mean 'transform'?)");
  CHECK(didYouMean("colour", attrs) == "");  // nothing close
  CHECK(didYouMean("x", attrs) == "");       // short words do not match everything
  CHECK(closestName("ix", attrs) == "id");
}
