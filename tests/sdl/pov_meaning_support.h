// Support for the tests of POV-Ray's meaning (sdl/pov_*.h): running POV-Ray on a script and
// reading what it prints, and holding a Lucent scene built from the importer's structs to
// POV-Ray's own image of the equivalent hand-written .pov, with the gallery's bounds
// (tests/gallery/compare_scene.sh).
#pragma once

#include "../temp_dir.h"

#include "lang/parser.h"
#include "povray/image_compare.h"
#include "povray/pov_runner.h"
#include "render/renderer.h"
#include "render/working_gamma.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

namespace lucent::test {

// POV-Ray's messages (its #debug output included) for a scene that renders nothing.
inline std::string povrayMessages(const std::string& script) {
  const auto povray = findPovray();
  REQUIRE(povray);  // POV-Ray is part of the test set-up (scripts/install-deps)
  TempDir dir("sdl-pov");
  const std::string input = dir.write("script.pov", script).string();
  const std::string log = dir.file("log.txt");
  ProcessResult run =
      runProcess(*povray, {"+I" + input, "+W8", "+H8", "-D", "-F", "-V", "-GS", "-GR"},
                 dir.path.string(), log);
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  INFO(text);
  REQUIRE(run.exitStatus == 0);
  return text;
}

// The numbers printed after `label` on its line.
inline std::vector<double> printedNumbers(const std::string& messages, const std::string& label) {
  const size_t at = messages.find(label);
  REQUIRE(at != std::string::npos);
  std::istringstream line(messages.substr(at + label.size(), messages.find('\n', at) - at));
  std::vector<double> numbers;
  for (double v; line >> v;) numbers.push_back(v);
  return numbers;
}

// A scene whose geometry is read from XML (in Lucent's space, z already negated), for the
// structs under test to fill its camera, lights, materials and settings.
inline std::unique_ptr<Scene> geometryScene(const std::string& body, int width, int height) {
  ParseResult parsed =
      // The XML language needs a camera; the test replaces it with the imported one.
      parseSceneString("<scene version=\"1\">\n<camera/>\n" + body + "\n</scene>\n", "test.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  parsed.scene->render.width = width;
  parsed.scene->render.height = height;
  return std::move(parsed.scene);
}

// The material with `id` in the scene (the XML's placeholder), to be replaced.
inline Material& materialNamed(Scene& scene, const std::string& id) {
  for (Material& m : scene.materials)
    if (m.id == id) return m;
  FAIL("no material '" << id << "'");
  return scene.materials.front();
}

// The light `lucent render` writes: a scene with a working gamma has its values decoded, as
// POV-Ray (File_Gamma=1.0, renderWithPovray) writes them.
inline RgbImage renderWithLucent(const Scene& scene) {
  REQUIRE(!scene.cameras.empty());
  World world(scene);
  Renderer renderer(world, scene.cameras.front());
  RenderControl control;
  control.threads = 1;
  RenderResult result = renderer.render(control);
  workingToLinear(scene.render.workingGamma, result.image);
  RgbImage out(result.image.width, result.image.height);
  for (size_t p = 0; p < result.image.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) out.rgb[p * 3 + c] = result.image.pixels[p][c];
  return out;
}

inline RgbImage renderWithPovray(const std::string& pov, int width, int height) {
  const auto povray = findPovray();
  REQUIRE(povray);
  TempDir dir("sdl-image");
  PovrayRender job;
  job.input = dir.write("scene.pov", pov).string();
  job.output = dir.file("povray.png");
  job.width = width;
  job.height = height;
  job.threads = 1;
  const std::string log = dir.file("log.txt");
  ProcessResult run = runProcess(*povray, povrayArguments(job), dir.path.string(), log);
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  INFO(text);
  REQUIRE(run.exitStatus == 0);
  return readLinear16Png(job.output);
}

// The gallery's bounds: PSNR >= 40 dB, SSIM >= 0.99, at most 1 % of the pixels off by more
// than 2/255, on sRGB-encoded values. A scene with a known, documented difference from
// POV-Ray lowers minPsnr, as a gallery scene raises its own bound, with the reason beside it.
inline ImageMetrics requireSameImage(const Scene& scene, const std::string& pov,
                                     double minPsnr = 40.0) {
  const RgbImage lucent = srgbEncoded(renderWithLucent(scene));
  const RgbImage povray =
      srgbEncoded(renderWithPovray(pov, scene.render.width, scene.render.height));
  const ImageMetrics m = compareImages(lucent, povray, 2.0 / 255.0);
  INFO("PSNR " << m.psnr << " dB, SSIM " << m.ssim << ", " << 100.0 * m.shareOver
               << " % of pixels off by more than 2/255, largest " << m.maxDiff << " at (" << m.maxX
               << ", " << m.maxY << ")");
  CHECK(m.psnr >= minPsnr);
  CHECK(m.ssim >= 0.99);
  CHECK(m.shareOver <= 0.01);
  return m;
}

}  // namespace lucent::test
