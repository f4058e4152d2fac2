// Averages of materials (Tracer::shadeAverage): POV-Ray's average of textures shades every
// entry whole and averages the colours by weight; shadow rays average what the entries let
// through. And the entries of a map are shaded at its warped point (render/map_entries.h),
// as POV-Ray hands them the point after the map's warps.
#include "scene_builder.h"

#include "../support/scene_text.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "material_average.xml", "<camera position=\"0 5 5\" look-at=\"0 0 0\"/>");
}

void checkColor(const Color& got, const Color& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-5));
}

Color down(const World& world, double x, double z) {
  return traceOne(world, Ray(Vec3(x, 1, z), Vec3(0, -1, 0)));
}

}  // namespace

TEST_CASE("an average of materials: each entry shaded whole, the colours weighted",
          "[render][material-map][average]") {
  // Ambient light only: red (weight 3) and blue (1) give (0.75, 0, 0.25); a mirror of the
  // 0.8 grey background and a matte green, equally weighted, give half of each.
  auto scene = parse(R"XML(<render ambient="1" background="0.8 0.8 0.8"/>
    <material id="red" ambient="1 0 0"/>
    <box min="-2 -1 -1" max="0 0 1"><material><material-map><average/>
      <entry weight="3" material="red"/>
      <entry weight="1"><material ambient="0 0 1"/></entry>
    </material-map></material></box>
    <box min="0 -1 -1" max="2 0 1"><material><material-map><average/>
      <entry weight="1"><material reflective="1"/></entry>
      <entry weight="1"><material ambient="0 0.5 0"/></entry>
    </material-map></material></box>)XML");
  World world(*scene);
  checkColor(down(world, -1, 0.3), Color(0.75f, 0, 0.25f));
  checkColor(down(world, -0.2, -0.7), Color(0.75f, 0, 0.25f));  // the same everywhere
  checkColor(down(world, 1, 0.3), Color(0.4f, 0.65f, 0.4f));
}

TEST_CASE("an average of materials: light through an entry, and a shadow ray's mean",
          "[render][material-map][average]") {
  // A clear entry (weight 1) and an opaque ambient 0.2 one (weight 3): a quarter of the
  // background is seen, and the floor under the sheet gets a quarter of the light.
  auto sheet = parse(R"XML(<render ambient="1" background="0.4 0.6 0.8"/>
    <disc center="0 0 0" normal="0 1 0" radius="10"><material><material-map><average/>
      <entry weight="1"><material transmissive="1"/></entry>
      <entry weight="3"><material ambient="0.2"/></entry>
    </material-map></material></disc>)XML");
  World world(*sheet);
  checkColor(down(world, 0.5, 0.3), Color(0.4f, 0.6f, 0.8f) * 0.25f + Color(0.15f));

  auto shadow = parse(R"XML(<light type="directional" direction="0 -1 0" color="1"/>
    <disc center="0 1 0" normal="0 1 0" radius="100"><material><material-map><average/>
      <entry weight="1"><material transmissive="1"/></entry>
      <entry weight="3"><material/></entry>
    </material-map></material></disc>
    <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>)XML");
  World world2(*shadow);
  checkColor(traceOne(world2, Ray(Vec3(0.25, 0.5, 0.3), Vec3(0, -1, 0))), Color(0.25f));
}

TEST_CASE("a material map's entries are shaded at the point after its warps",
          "[render][material-map][warp]") {
  // One entry whose ambient colour is frac(z) (a gradient along z). The map's repeat warp
  // moves every slab n of x (width 1) by n·(0, 0, 0.5): POV-Ray evaluates the entry there,
  // frac(z + 0.5) in the slab [1, 2). The average's translate is undone for its entries
  // (they are placed from the object's space), so only the warp moves them.
  const std::string entry = R"XML(<entry weight="1"><material ambient="1" diffuse="0">
      <pattern type="gradient" axis="0 0 1"/></material></entry>)XML";
  auto scene = parse(R"XML(<render ambient="1" background="0 0 0"/>
    <box min="-3 -1 -3" max="3 0 0"><material><material-map>
      <pattern type="gradient" axis="1 0 0">
        <warp type="repeat" direction="1 0 0" offset="0 0 0.5"/>
      </pattern>
      <entry at="0"><material ambient="1" diffuse="0">
        <pattern type="gradient" axis="0 0 1"/></material></entry>
    </material-map></material></box>
    <box min="-3 -1 0" max="3 0 3"><material><material-map>
      <average transform="translate(0 0 0.1)">
        <warp type="repeat" direction="1 0 0" offset="0 0 0.5"/>
      </average>)XML" +
                     entry + R"XML(
    </material-map></material></box>)XML");
  World world(*scene);
  auto grey = [&](double x, double z) { return down(world, x, z).r; };
  CHECK(grey(0.5, -0.8) == Approx(0.2).margin(1e-6));   // slab 0: unmoved
  CHECK(grey(1.5, -0.8) == Approx(0.7).margin(1e-6));   // slab 1: z + 0.5
  CHECK(grey(2.5, -0.8) == Approx(0.2).margin(1e-6));   // slab 2: z + 1
  CHECK(grey(-0.5, -0.6) == Approx(0.9).margin(1e-6));  // slab -1: z − 0.5
  CHECK(grey(0.5, 0.3) == Approx(0.3).margin(1e-6));
  CHECK(grey(1.5, 0.3) == Approx(0.8).margin(1e-6));
  CHECK(grey(-1.5, 0.3) == Approx(0.3).margin(1e-6));  // slab -2: z − 1
}
