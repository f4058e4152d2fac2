// The panini fov limit, checked at load: for distance d > 1 the horizontal plane coordinate
// h(phi) = (d+1) sin(phi) / (d + cos(phi)) peaks at cos(phi) = -1/d and folds back beyond,
// so a horizontal fov must stay below 2 acos(-1/d) (2 acos(-d) for d <= 1). The parser must
// refuse exactly what the projection cannot frame, with file:line:col, and the largest fov
// it accepts must render.
#include "camera_checks.h"

#include "lang/parser.h"
#include "render/panini.h"
#include "render/renderer.h"
#include "scenegraph/world.h"

#include <fmt/format.h>

#include <cmath>

using namespace lucent;
using namespace lucent::camtest;

namespace {

std::string paniniScene(double distance, double fov, const std::string& extra = "") {
  // An emissive sphere all around the camera: every pixel with a ray is green, a pixel
  // without one gets the red background.
  return fmt::format(R"XML(<scene version="1">
  <render width="48" height="36" background="1 0 0"/>
  <camera type="panini" distance="{}" fov="{:.17g}"{}/>
  <sphere radius="50"><material emissive="0 1 0"/></sphere>
</scene>
)XML",
                     distance, fov, extra);
}

bool accepted(double distance, double fov) {
  return parseSceneString(paniniScene(distance, fov), "limit.xml").scene != nullptr;
}

std::string errors(const std::string& xml) {
  ParseResult r = parseSceneString(xml, "limit.xml");
  std::string all;
  for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
  return all;
}

// 2 acos(-1/d) in degrees, the published fold-back longitude doubled (long double, so it
// does not share the parser's rounding).
double foldBackFov(double d) {
  return static_cast<double>(2.0L * std::acos(-1.0L / d) * 180.0L / 3.141592653589793238462643L);
}

}  // namespace

TEST_CASE("panini distance above 1: the parser refuses a fov at or beyond 2 acos(-1/d)",
          "[cameras][panini][lang]") {
  // 2 acos(-1/2) = 240 exactly: the limit itself is refused, a hair below is fine.
  CHECK(errors(paniniScene(2.0, 240.0)) ==
        "limit.xml:3:43: error: <camera> attribute 'fov': with distance 2 a panini camera's fov "
        "must be below 240 (beyond 120 degrees from the axis the projection folds back)\n");
  CHECK(errors(paniniScene(2.0, 245.0)) != "");
  CHECK(accepted(2.0, 239.999));
  // d = 4: 2 acos(-1/4) = 208.955 degrees.
  CHECK(accepted(4.0, 208.95));
  CHECK_FALSE(accepted(4.0, 208.96));
  // d <= 1 keeps its own bound 2 acos(-d): 360 for d = 1, 240 for d = 0.5.
  CHECK(accepted(1.0, 359.9));
  CHECK_FALSE(accepted(1.0, 360.0));
  CHECK(accepted(0.5, 239.9));
  CHECK_FALSE(accepted(0.5, 240.0));
}

TEST_CASE("panini: the largest fov the parser accepts renders, the next one the projection refuses",
          "[cameras][panini][lang][render]") {
  for (double d : {1.25, 2.0, 3.0, 10.0}) {
    INFO("distance " << d);
    // Bisect (over doubles, through the parser) to the largest accepted fov: it lies
    // within 1e-9 degrees of the analytic limit, which is itself refused.
    double fov = foldBackFov(d) - 1e-7, refused = foldBackFov(d);
    REQUIRE(accepted(d, fov));
    REQUIRE_FALSE(accepted(d, refused));
    while (std::nextafter(fov, refused) != refused) {
      double mid = 0.5 * (fov + refused);
      (accepted(d, mid) ? fov : refused) = mid;
    }
    CHECK(refused - fov > 0.0);
    CHECK(foldBackFov(d) - fov < 1e-9);

    ParseResult parsed = parseSceneString(paniniScene(d, fov), "limit.xml");
    REQUIRE(parsed.scene);
    const Scene& scene = *parsed.scene;
    const Camera& cam = scene.cameras.at(0);
    // The projection frames it, and its edges look (almost) at the fold-back longitude.
    auto p = makeProjection(cam, 48, 36);
    Vec3 edge = rayAt(*p, Vec2(48.0, 18.0)).d;  // cam looks down -z, right = +x
    double longitude = std::atan2(edge.x, -edge.z);
    CHECK(longitude == Approx(radians(fov / 2.0)).epsilon(1e-6));
    // One double more is refused by the projection as well.
    Camera wider = cam;
    wider.fov = refused;
    CHECK_THROWS_AS(makeProjection(wider, 48, 36), LocatedError);

    // The render: every pixel has a ray, so none shows the background.
    World world(scene);
    Renderer renderer(world, cam);
    Image image = renderer.render().image;
    int background = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (image.at(x, y) != Color(0.0f, 1.0f, 0.0f)) ++background;
    CHECK(background == 0);
  }
}

TEST_CASE("panini fov limits that do not depend on the image size are refused at load",
          "[cameras][panini][lang]") {
  // A vertical fov spans the latitude of the centre column: below 180 at any distance.
  CHECK(errors(paniniScene(1.0, 180.0, R"( fov-axis="vertical")")) ==
        "limit.xml:3:43: error: <camera> attribute 'fov': a panini camera's vertical fov must be "
        "below 180 (the latitude at the top edge stays below 90 degrees)\n");
  CHECK(errors(paniniScene(1.0, 179.0, R"( fov-axis="vertical")")) == "");
  // The hard squeeze needs the image within 90 degrees of the axis horizontally.
  CHECK(errors(paniniScene(1.0, 180.0, R"( vertical-compression="0.5")")) ==
        "limit.xml:3:43: error: <camera> attribute 'fov': with vertical-compression above 0 a "
        "panini camera's horizontal fov must be below 180\n");
  CHECK(errors(paniniScene(1.0, 179.0, R"( vertical-compression="0.5")")) == "");
  // The largest accepted fov of both is framed by the projection.
  const double below180 = std::nextafter(180.0, 0.0);
  for (const char* extra : {R"( fov-axis="vertical")", R"( vertical-compression="0.5")"}) {
    INFO(extra);
    ParseResult ok = parseSceneString(paniniScene(1.0, below180, extra), "limit.xml");
    REQUIRE(ok.scene);
    CHECK_NOTHROW(makeProjection(ok.scene->cameras.at(0), 48, 36));
  }
  // What depends on the aspect ratio is left to the projection, which names the camera's
  // location: a vertical fov of 170 at distance 3 needs a plane wider than the peak
  // sqrt((d+1)/(d-1)) at 4:3.
  ParseResult r = parseSceneString(paniniScene(3.0, 170.0, R"( fov-axis="vertical")"), "limit.xml");
  REQUIRE(r.scene);
  CHECK_THROWS_WITH(makeProjection(r.scene->cameras.at(0), 48, 36),
                    Catch::StartsWith("limit.xml:3:3: error: a panini camera with distance 3"));
}
