// `lucent check`: the summary on stdout, every diagnostic on stderr, and the contract's
// exit statuses (0 valid, 2 invalid scene, 3 unreadable scene file).
#include "run_lucent.h"

#include <catch2/catch.hpp>

using lucent::test::runLucent;
using lucent::test::sourcePath;

TEST_CASE("lang: lucent check prints a summary of a valid scene and exits 0", "[lang][check]") {
  std::string scene = sourcePath("tests/lang/valid/defs_use.xml");
  auto r = runLucent("check '" + scene + "'");
  CHECK(r.status == 0);
  CHECK(r.out == "scene: " + scene +
                     "\n"
                     "image: 640x480, 1 sample per pixel, max depth 5\n"
                     "cameras: 1 (pinhole: 1)\n"
                     "lights: 0\n"
                     "materials: 0\n"
                     "nodes: 9 (box: 1, cylinder: 1, group: 1, sphere: 1, use: 5)\n"
                     "defs: 1\n"
                     "instances: 7\n"
                     "triangles: 0\n"
                     "csg depth: 0\n");
}

TEST_CASE("lang: lucent check prints every error of an invalid scene to stderr and exits 2",
          "[lang][check]") {
  std::string scene = sourcePath("tests/bad/scenes/multiple_errors.xml");
  auto r = runLucent("check '" + scene + "'");
  CHECK(r.status == 2);
  CHECK(r.out ==
        "E: " + scene +
            ":2:16: error: <camera> attribute 'fov': expected an angle between 0 and 180, got '0'\n"
            "E: " +
            scene +
            ":3:19: error: <sphere> attribute 'radius': expected a positive number, got '-1'\n"
            "E: " +
            scene +
            ":4:13: error: <box> attribute 'min': expected 3 numbers, got 2 ('1 1')\n"
            "E: " +
            scene +
            ":5:10: error: <torus>: unknown attribute 'majr' (did you mean 'major'?)\n"
            "E: " +
            scene + ": 4 errors; the scene is invalid\n");
}

TEST_CASE("lang: lucent check takes -D and --allow-path, a missing scene file exits 3",
          "[lang][check]") {
  std::string params = sourcePath("tests/lang/valid/params.xml");
  auto r = runLucent("check '" + params + "' -D r=-1");
  CHECK(r.status == 2);
  CHECK_THAT(r.out,
             Catch::Contains("<sphere> attribute 'radius': expected a positive number, got '-1'"));

  std::string escape = sourcePath("tests/bad/scenes/include_escapes_folder.xml");
  CHECK(runLucent("check '" + escape + "'").status == 2);
  auto allowed =
      runLucent("check '" + escape + "' --allow-path '" + sourcePath("tests/lang/valid") + "'");
  CHECK(allowed.status == 0);
  CHECK_THAT(allowed.out, Catch::Contains("nodes: 5 (box: 1, difference: 1, plane: 1, sphere: 2)"));

  auto missing = runLucent("check /nonexistent/scene.xml");
  CHECK(missing.status == 3);
  CHECK(missing.out ==
        "E: /nonexistent/scene.xml: error: cannot read the scene file: no such file\n");
}
