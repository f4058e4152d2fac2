// handedness on an oriented area light: read (right by default), written back by `lucent
// convert`, refused without orient; export-pov warns for left (POV-Ray turns the disc as
// right in the exported coordinates).
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kOriented =
    "<light type=\"area\" position=\"0 5 0\" u=\"1 0 0\" v=\"0 0 1\" samples=\"3 3\" "
    "orient=\"true\"";

}  // namespace

TEST_CASE("lang: an oriented light's handedness is read and written back", "[lang][light]") {
  auto plain = parseClean(std::string(kOriented) + "/>");
  REQUIRE(plain->lights.size() == 1);
  CHECK(plain->lights[0].handedness == Handedness::Right);
  CHECK(writeSceneXml(*plain, WriteOptions{}).find("handedness") == std::string::npos);

  auto left = parseClean(std::string(kOriented) + " handedness=\"left\"/>");
  CHECK(left->lights[0].handedness == Handedness::Left);
  const std::string text = writeSceneXml(*left, WriteOptions{});
  INFO(text);
  CHECK(text.find("handedness=\"left\"") != std::string::npos);
  ParseResult again = parseSceneString(text, "again.xml");
  REQUIRE(again.scene);
  CHECK(again.scene->lights[0].handedness == Handedness::Left);

  const PovExport pov = exportPov(*left);
  CHECK(pov.ok());
  CHECK(pov.text.find("orient") != std::string::npos);
  bool warned = false;
  for (const PovIssue& i : pov.issues)
    warned = warned ||
             i.str().find("handedness=\"left\" has no POV-Ray equivalent") != std::string::npos;
  CHECK(warned);
}
