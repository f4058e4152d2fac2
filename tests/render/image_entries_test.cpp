// Images as entries of maps and lists of pigments (POV-Ray's image_map in a pigment_map or
// a block pattern's list): a 2 x 2 image written here, read at points worked out by hand
// through the map's placement and the entry's own, blended as entries are.
#include "scene_builder.h"

#include "app/image_output.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include <unistd.h>

using namespace lucent;
using namespace lucent::test;

namespace {

// Red | green over blue | white (row 0 the top).
struct QuadImage {
  std::string path;
  QuadImage() {
    // Beside the scene (the working folder), which the scene may read.
    path = (std::filesystem::current_path() /
            ("lucent-image-entries-" + std::to_string(::getpid()) + ".png"))
               .string();
    Image img(2, 2);
    img.at(0, 0) = Color(1, 0, 0);
    img.at(1, 0) = Color(0, 1, 0);
    img.at(0, 1) = Color(0, 0, 1);
    img.at(1, 1) = Color(1, 1, 1);
    writeImageFile(img, path);
  }
  ~QuadImage() { std::filesystem::remove(path); }
};

// A floor y = 0 seen from above, its material ambient 1 without diffuse: its colour is the
// texture's as it is.
std::unique_ptr<Scene> floorOf(const std::string& texture) {
  ParseResult r = parseSceneString(
      R"XML(<scene version="1"><camera position="0 5 5" look-at="0 0 0"/><render ambient="1"/>
      <plane><material ambient="1" diffuse="0">)XML" +
          texture + "</material></plane></scene>",
      "entries.xml");
  std::string all;
  for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
  INFO(all);
  REQUIRE(r.scene);
  return std::move(r.scene);
}

Color down(const Scene& scene, double x, double z) {
  World world(scene);
  return traceOne(world, Ray(Vec3(x, 2, z), Vec3(0, -1, 0)));
}

void checkColour(const Color& got, const Color& want) {
  INFO("got " << got.r << " " << got.g << " " << got.b);
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-5));
}

}  // namespace

TEST_CASE(
    "an image entry of a pigment map is projected from the map's point through its own "
    "transform",
    "[render][texture][image-map][pigment-map]") {
  QuadImage image;
  // The map: gradient x over 4 units, its point p/4 for the floor point p = (x, 0, z). The
  // image entry, laid flat at half size in the map's space, reads (x/2, z/2) (rotate-x(90)
  // undone takes (a, 0, c) to (a, c, 0)); planar: columns at x < 0.5 and above, rows at
  // y < 0.5 (blue | white) and above (red | green). The entry at 0.25 is the image, at
  // 0.75 a grey; between them a linear blend.
  auto scene = floorOf(
      R"X(<pattern type="gradient" axis="1 0 0" transform="scale(4)"><pigment-map>
      <entry at="0.25"><image src=")X" +
      image.path +
      R"X(" projection="planar" interpolate="none" transform="scale(0.5) rotate-x(90)"/></entry>
      <entry at="0.75" color="0.5"/></pigment-map></pattern>)X");
  // Value 0.1: the image alone, at (0.2, 0.2): blue; at (0.2, 0.8): red.
  checkColour(down(*scene, 0.4, 0.4), Color(0, 0, 1));
  checkColour(down(*scene, 0.4, 1.6), Color(1, 0, 0));
  // Value 0.4: 0.7 of the image at (0.8, 0.8), green, and 0.3 of the grey.
  checkColour(down(*scene, 1.6, 1.6), Color(0.15f, 0.85f, 0.15f));
  // Value 0.55: 0.4 of the image at (1.1, 0.2), repeated: (0.1, 0.2), blue; 0.6 of grey.
  checkColour(down(*scene, 2.2, 0.4), Color(0.3f, 0.3f, 0.7f));
}

TEST_CASE("image entries of a checker's list: once clear off the image, transmit all added",
          "[render][texture][image-map][pigment-map]") {
  QuadImage image;
  // The checker's point of the floor point (x, 0, z) is (x, z, 0.5): off the cells'
  // boundary plane. Its even cells show the first image (once, moved by (0.25, 0.25)), its
  // odd cells the second (repeated, transmit 0.25 on every pixel).
  auto scene = floorOf(
      R"X(<checker transform="translate(0 0 -0.5) rotate-x(90)"><pigment-list>
      <entry><image src=")X" +
      image.path +
      R"X(" projection="planar" interpolate="none" once="true"
      transform="translate(0.25 0.25 0)"/></entry><entry><image src=")X" +
      image.path +
      R"X(" projection="planar" interpolate="none" transmit="0.25"/></entry>
      </pigment-list></checker>)X");
  // (0.5, 0.4): an even cell; the first image at (0.25, 0.15): blue.
  checkColour(down(*scene, 0.5, 0.4), Color(0, 0, 1));
  // (0.9, 0.9): the first image at (0.65, 0.65): green.
  checkColour(down(*scene, 0.9, 0.9), Color(0, 1, 0));
  // (0.1, 0.1): (-0.15, -0.15), off the once image: clear (transmit 1), so the floor shows
  // nothing of itself and lets through the black background.
  checkColour(down(*scene, 0.1, 0.1), Color(0, 0, 0));
  // (1.3, 0.8): an odd cell; the second image at (0.3, 0.8): red, 0.75 of it (1 - transmit;
  // the black behind adds nothing).
  checkColour(down(*scene, 1.3, 0.8), Color(0.75f, 0, 0));
}
