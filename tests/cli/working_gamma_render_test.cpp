// <render working-gamma> (POV-Ray's assumed_gamma): the image `lucent render` writes holds
// the computed values decoded to light, an image texture's texels meet them encoded, and the
// POV-Ray importer takes the gamma POV-Ray renders with (docs/scene-language.md, <render>).
#include "run_lucent.h"

#include "app/image_output.h"
#include "images/srgb_decoding.h"
#include "render/image.h"
#include "render/image_read.h"
#include "render/working_gamma.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace lucent;
using namespace lucent::test;

namespace {

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// The 8-bit code value of the centre pixel's red, as the PNG stores it.
int centreByte(const std::filesystem::path& png) {
  const Image image = readImageFile(png.string(), PixelDecoding::AsStored);
  return static_cast<int>(std::lround(image.at(image.width / 2, image.height / 2).r * 255.0f));
}

}  // namespace

TEST_CASE("working gamma: the transfer and its inverse", "[render][gamma]") {
  const WorkingGamma power{false, 2.2};
  CHECK(workingToLinear(power, 0.5) == Approx(std::pow(0.5, 2.2)));
  CHECK(linearToWorking(power, std::pow(0.5, 2.2)) == Approx(0.5));
  CHECK(workingToLinear(power, -0.5) == Approx(-std::pow(0.5, 2.2)));  // the sign kept
  const WorkingGamma srgb{true, 1.0};
  CHECK(workingToLinear(srgb, 0.5) == Approx(0.21404114));
  CHECK(linearToWorking(srgb, 0.21404114) == Approx(0.5));
  CHECK(workingToLinear(WorkingGamma{}, 0.3) == 0.3);
}

TEST_CASE("render writes a working-gamma scene's values decoded to light", "[cli][gamma]") {
  TempFolder dir("lucent-working-gamma");
  // The background alone: the value 0.5 everywhere.
  const std::string scene =
      R"(<scene version="1"><render width="8" height="6" background="0.5 0.5 0.5" working-gamma="GAMMA"/>)"
      R"(<camera type="pinhole" position="0 0 5" look-at="0 0 0"/></scene>)";
  auto render = [&](const std::string& gamma) {
    std::string text = scene;
    text.replace(text.find("GAMMA"), 5, gamma);
    writeFile(dir.path() / "s.xml", text);
    const LucentRun r = runLucent("render -q '" + (dir.path() / "s.xml").string() + "' -o '" +
                                  (dir.path() / "s.png").string() + "'");
    REQUIRE(r.status == 0);
    return centreByte(dir.path() / "s.png");
  };
  CHECK(render("1") == srgbByte(0.5f));
  CHECK(render("2.2") == srgbByte(static_cast<float>(std::pow(0.5, 2.2))));
  CHECK(render("srgb") == 128);  // sRGB's curve undone by the PNG's: the value itself
  CHECK(srgbByte(0.5f) != 128);
}

TEST_CASE("an image texture's texels come back to the same bytes under a working gamma",
          "[cli][gamma]") {
  TempFolder dir("lucent-working-gamma-texture");
  // A texture of the byte 90, shown by ambient light alone.
  Image texture(4, 4);
  for (Color& c : texture.pixels) c = Color(static_cast<float>(srgbToLinear(90.0 / 255.0)));
  writeImageFile(texture, (dir.path() / "t.png").string());
  REQUIRE(centreByte(dir.path() / "t.png") == 90);
  for (const std::string gamma : {"1", "1.8", "srgb"}) {
    writeFile(dir.path() / "s.xml",
              R"(<scene version="1"><render width="8" height="6" working-gamma=")" + gamma +
                  R"("/><camera type="orthographic" width="1" position="0 0 5" look-at="0 0 0"/>)"
                  R"(<box min="-2 -2 -1" max="2 2 0"><material ambient="1" diffuse="0">)"
                  R"(<image src="t.png" projection="planar"/></material></box></scene>)");
    const LucentRun r = runLucent("render -q '" + (dir.path() / "s.xml").string() + "' -o '" +
                                  (dir.path() / "s.png").string() + "'");
    REQUIRE(r.status == 0);
    CHECK(centreByte(dir.path() / "s.png") == 90);
  }
}

TEST_CASE("an image's own gamma decodes its file's values", "[cli][gamma][image-map]") {
  TempFolder dir("lucent-image-gamma");
  // A texture whose stored byte is 20 (dark, where sRGB's curve and a power of 2.2 part), shown by
  // ambient light alone in a linear scene: the light written is the byte decoded by the image's
  // gamma.
  Image texture(4, 4);
  for (Color& c : texture.pixels) c = Color(static_cast<float>(srgbToLinear(20.0 / 255.0)));
  writeImageFile(texture, (dir.path() / "t.png").string());
  REQUIRE(centreByte(dir.path() / "t.png") == 20);
  auto render = [&](const std::string& gammaAttribute) {
    writeFile(dir.path() / "s.xml",
              R"(<scene version="1"><render width="8" height="6"/>)"
              R"(<camera type="orthographic" width="1" position="0 0 5" look-at="0 0 0"/>)"
              R"(<box min="-2 -2 -1" max="2 2 0"><material ambient="1" diffuse="0">)"
              R"(<image src="t.png" projection="planar")" +
                  gammaAttribute + R"(/></material></box></scene>)");
    const LucentRun r = runLucent("render -q '" + (dir.path() / "s.xml").string() + "' -o '" +
                                  (dir.path() / "s.png").string() + "'");
    REQUIRE(r.status == 0);
    return centreByte(dir.path() / "s.png");
  };
  CHECK(render("") == 20);  // Lucent's rule: an 8-bit file is sRGB
  CHECK(render(R"( gamma="srgb")") == 20);
  CHECK(render(R"( gamma="1")") == srgbByte(20.0f / 255.0f));  // the values are light
  CHECK(render(R"( gamma="2.2")") == srgbByte(static_cast<float>(std::pow(20.0 / 255.0, 2.2))));
  CHECK(srgbByte(static_cast<float>(std::pow(20.0 / 255.0, 2.2))) != 20);
}

TEST_CASE("the importer renders with POV-Ray's working gamma", "[cli][gamma][sdl]") {
  TempFolder dir("lucent-working-gamma-pov");
  auto render = [&](const std::string& text) {
    writeFile(dir.path() / "s.pov", text);
    const LucentRun r = runLucent("render -q -w 8 -h 6 '" + (dir.path() / "s.pov").string() +
                                  "' -o '" + (dir.path() / "s.png").string() + "'");
    REQUIRE(r.status == 0);
    return centreByte(dir.path() / "s.png");
  };
  const int at22 = srgbByte(static_cast<float>(std::pow(0.5, 2.2)));
  CHECK(render("#version 3.7; global_settings { assumed_gamma 2.2 } background { rgb 0.5 }") ==
        at22);
  // The first assumed_gamma counts, as in POV-Ray.
  CHECK(render("#version 3.7; global_settings { assumed_gamma 2.2 assumed_gamma 1 } "
               "background { rgb 0.5 }") == at22);
  CHECK(render("#version 3.7; global_settings { assumed_gamma 1 } background { rgb 0.5 }") ==
        srgbByte(0.5f));
  // No assumed_gamma: 1.0 under 3.7; gamma off (the values written as they are) under 3.6.
  CHECK(render("#version 3.7; background { rgb 0.5 }") == srgbByte(0.5f));
  CHECK(render("#version 3.6; background { rgb 0.5 }") == 128);
  CHECK(render("#version 3.7; global_settings { assumed_gamma srgb } background { rgb 0.5 }") ==
        128);
  // convert writes the gamma, and the XML renders to the same bytes.
  render("#version 3.7; global_settings { assumed_gamma 1.8 } background { rgb 0.3 }");
  const LucentRun converted = runLucent("convert '" + (dir.path() / "s.pov").string() + "' -o '" +
                                        (dir.path() / "c.xml").string() + "'");
  REQUIRE(converted.status == 0);
  const LucentRun again = runLucent("render -q '" + (dir.path() / "c.xml").string() + "' -o '" +
                                    (dir.path() / "c.png").string() + "'");
  REQUIRE(again.status == 0);
  CHECK(centreByte(dir.path() / "c.png") == centreByte(dir.path() / "s.png"));
  CHECK(centreByte(dir.path() / "c.png") == srgbByte(static_cast<float>(std::pow(0.3, 1.8))));
}
