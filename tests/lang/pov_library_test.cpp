// The `pov:` names of the XML language: POV-Ray's standard colours and textures, made from
// POV-Ray's include files by the importer when Lucent is built (povlib/, sdl/pov_library.h).
#include "../support/scene_text.h"

#include "lang/pov_library.h"
#include "lang/scene_writer.h"
#include "sdl/pov_library.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

using namespace lucent;
using namespace lucent::test;

namespace {

// The same XML text, its numbers equal to within 1e-12 of their size (a transform read back
// is inverted twice, which may change its last digits) or of 1e-15 (zeros).
bool sameText(const std::string& a, const std::string& b) {
  auto isNumberChar = [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == 'e' ||
           c == '+';
  };
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) || a[i] == '-') {
      size_t ei = i, ej = j;
      while (ei < a.size() && isNumberChar(a[ei])) ++ei;
      while (ej < b.size() && isNumberChar(b[ej])) ++ej;
      char* end = nullptr;
      const double x = std::strtod(a.substr(i, ei - i).c_str(), &end);
      const double y = std::strtod(b.substr(j, ej - j).c_str(), &end);
      if (std::abs(x - y) > 1e-12 * std::max(std::abs(x), std::abs(y)) + 1e-15) return false;
      i = ei;
      j = ej;
      continue;
    }
    if (a[i] != b[j]) return false;
    ++i;
    ++j;
  }
  return i == a.size();
}

}  // namespace

TEST_CASE("pov: colours are colors.inc's, linear as POV-Ray's with assumed_gamma 1",
          "[lang][pov-library]") {
  auto s = parseClean(
      "<material id=\"a\" diffuse=\"pov:MediumAquamarine\" specular=\"pov:White\"/>"
      "<material id=\"b\" diffuse=\"pov:Orange\"/><sphere material=\"a\"/><sphere "
      "material=\"b\"/>");
  // colors.inc: MediumAquamarine = color red 0.196078 green 0.8 blue 0.6,
  // Orange = color red 1 green 0.5 blue 0 (stored as single-precision floats).
  const Material& a = materialNamed(*s, "a");
  CHECK(a.diffuse.r == Approx(0.196078).epsilon(1e-6));
  CHECK(a.diffuse.g == Approx(0.8).epsilon(1e-6));
  CHECK(a.diffuse.b == Approx(0.6).epsilon(1e-6));
  CHECK(a.specular == Color(1.0f));
  CHECK(materialNamed(*s, "b").diffuse == Color(1.0f, 0.5f, 0.0f));
}

TEST_CASE("pov: textures are read on their first use, once, and serve as a base",
          "[lang][pov-library]") {
  auto s = parseValid(
      "<material id=\"shiny-wood\" base=\"pov:T_Wood10\" reflective=\"0.2\"/>"
      "<sphere material=\"pov:T_Wood10\"/><sphere material=\"pov:T_Wood10\"/>"
      "<sphere material=\"shiny-wood\"/>");
  size_t woods = 0;
  for (const Material& m : s->materials) woods += m.id == "pov:T_Wood10";
  CHECK(woods == 1);
  const Material& wood = materialNamed(*s, "pov:T_Wood10");
  // woods.inc's T_Wood10: a wood pigment with a second, see-through wood layer over it.
  CHECK(wood.hasTexture());
  CHECK(wood.layers.size() == 1);
  CHECK(s->root->children[0]->material == s->root->children[1]->material);
  const Material& shiny = materialNamed(*s, "shiny-wood");
  CHECK(shiny.reflective == Color(0.2f));
  CHECK(shiny.layers.size() == 1);
}

TEST_CASE("pov: every library material reads back to the importer's own material",
          "[lang][pov-library]") {
  // The library made afresh by the importer, as the build makes it: every material of the
  // compiled-in library, read by the XML language and written back, is the importer's text.
  const sdl::PovLibraryText fresh = sdl::makePovLibrary(sdl::Options{});
  REQUIRE(fresh.materials > 400);
  REQUIRE(fresh.colours > 250);
  std::string body;
  for (const std::string& name : fresh.materialNames) body += "<sphere material=\"" + name + "\"/>";
  auto s = parseValid(body);
  REQUIRE(s->root->children.size() == fresh.materialNames.size());
  for (size_t i = 0; i < fresh.materialNames.size(); ++i) {
    const std::string& name = fresh.materialNames[i];
    INFO(name);
    Material m = s->materials.at(*s->root->children[i]->material);
    m.loc = SourceLoc{};  // as the library writes it, without the line it was read from
    const std::string text = writeMaterialXml(m, name, WriteOptions{});
    INFO(text);
    const size_t at = fresh.xml.find("<material id=\"" + name + "\"");
    REQUIRE(at != std::string::npos);
    CHECK(sameText(text, fresh.xml.substr(at - 2, text.size() + 200)));
  }
}

TEST_CASE("pov: names that are not in the library, or not of that kind, are located errors",
          "[lang][pov-library][bad]") {
  ParseResult r = parseBody("<sphere material=\"pov:T_Wod10\"/>");
  CHECK(messages(r) ==
        "test.xml:1:47: error: <sphere> attribute 'material': POV-Ray's library has no texture, "
        "pigment or material 'T_Wod10' (did you mean 'pov:T_Wood10'?)\n");
  r = parseBody("<sphere material=\"pov:White\"/>");
  CHECK_THAT(messages(r), Catch::Contains("'pov:White' is a colour: diffuse=\"pov:White\""));
  r = parseBody("<sphere><material diffuse=\"pov:T_Wood1\"/></sphere>");
  CHECK_THAT(messages(r), Catch::Contains("'pov:T_Wood1' is a texture: material=\"pov:T_Wood1\""));
  r = parseBody("<sphere><material diffuse=\"pov:Clear\"/></sphere>");
  CHECK_THAT(messages(r), Catch::Contains("'pov:Clear' has filter 1 and transmit 0"));
  r = parseBody("<material id=\"pov:Mine\" diffuse=\"1\"/><sphere material=\"pov:Mine\"/>");
  CHECK_THAT(messages(r), Catch::Contains("'pov:' names POV-Ray's library"));
  CHECK_FALSE(r.scene);
}
