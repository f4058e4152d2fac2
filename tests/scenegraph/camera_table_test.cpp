// The table of camera types and <camera> attributes (scenegraph/camera.cpp) and what is
// derived from it: the parser's names, attribute check and reads, the schema, `lucent
// check`'s counts, the POV-Ray exporter's keywords and the renderer's projections.
#include "../povray/pov_test_support.h"
#include "../support/scene_text.h"
#include "lang/schema.h"
#include "render/projection.h"
#include "scenegraph/camera.h"
#include "scenegraph/scene_summary.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

// A value every type that takes the attribute accepts, for the parser to get past it.
std::string sampleValue(const CameraAttribute& a) {
  const std::string& name = a.info.name;
  if (name == "name") return "cam";
  if (name == "transform") return "translate(0 1 0)";
  if (name == "position") return "0 1 5";
  if (name == "look-at") return "1 0 -1";
  if (name == "up") return "0 1 0";
  if (name == "fov") return "50";
  if (name == "far") return "100";
  if (name == "lenses") return "2 3";
  if (name == "image-plane") return "1.3 0 0.1  0 1 0";
  if (name == "cylinder-type") return "3";
  if (name == "rays-per-pixel") return "1";
  if (name == "distribution") return "1";
  if (name == "smooth") return "false";  // true is for distribution 3 only
  if (!a.info.choices.empty()) return std::string(a.info.choices.back());
  if (a.info.type == AttrType::Boolean) return "true";
  return "0.5";
}

// A mesh camera needs the faces of a <mesh> child.
std::string cameraWith(std::string_view type, const std::string& attributes = "") {
  const std::string head = "<camera type=\"" + std::string(type) + "\" " + attributes;
  if (type == "mesh")
    return head + "><mesh positions=\"0 0 0 1 0 0 0 1 0\" indices=\"0 1 2\"/></camera>";
  return head + "/>";
}

}  // namespace

TEST_CASE("camera table: a row per type in CameraType's order, names unique", "[camera][table]") {
  const auto& types = cameraTypes();
  REQUIRE(types.size() >= 9);
  std::set<std::string_view> names;
  for (size_t i = 0; i < types.size(); ++i) {
    INFO(types[i].name);
    CHECK(static_cast<size_t>(types[i].type) == i);
    CHECK(&cameraTypeInfo(types[i].type) == &types[i]);
    CHECK(std::string(cameraTypeName(types[i].type)) == types[i].name);
    CHECK_FALSE(types[i].name.empty());
    CHECK_FALSE(types[i].doc.empty());
    CHECK(names.insert(types[i].name).second);
    // A POV-Ray keyword comes with its writer and the words the export error lists it by
    // (the mesh camera's block, meshes and no frame, has a writer of its own:
    // povray/pov_mesh_camera.h).
    if (types[i].type != CameraType::Mesh)
      CHECK(types[i].pov.keyword.empty() == !types[i].pov.write);
    CHECK(types[i].pov.keyword.empty() == types[i].pov.listed.empty());
    // What frames the image when fov does not: said only then.
    if (types[i].fov) CHECK(types[i].noFov.empty());
  }
  std::set<std::string> attributes;
  for (const CameraAttribute& a : cameraAttributes()) {
    INFO(a.info.name);
    CHECK(attributes.insert(a.info.name).second);
    CHECK_FALSE(a.info.doc.empty());
    // Only the language's own attributes have no reader.
    if (!a.read)
      CHECK((a.info.name == "name" || a.info.name == "type" || a.info.name == "transform"));
  }
}

TEST_CASE("camera table: each type takes its attributes and names the owners of the others",
          "[camera][table][lang]") {
  for (const CameraTypeInfo& t : cameraTypes()) {
    for (const CameraAttribute& a : cameraAttributes()) {
      if (a.info.name == "type") continue;
      const std::string camera = cameraWith(t.name, a.info.name + "=\"" + sampleValue(a) + "\"");
      INFO(camera);
      ParseResult r = parseBody("", "cameras.xml", camera);
      const std::string said = messages(r);
      INFO(said);
      if (a.takenBy(t.type)) {
        CHECK(r.diagnostics.errorCount() == 0);
        // fov and fov-axis only warn where no field of view frames the image.
        const bool framing = a.info.name == "fov" || a.info.name == "fov-axis";
        CHECK(r.diagnostics.all().size() == (framing && !t.fov ? 1u : 0u));
        continue;
      }
      CHECK(r.diagnostics.errorCount() == 1);
      CHECK(said.find("this camera is " + std::string(t.name)) != std::string::npos);
      for (const CameraTypeInfo& owner : cameraTypes())
        if (a.takenBy(owner.type)) CHECK(said.find(std::string(owner.name)) != std::string::npos);
    }
  }
}

TEST_CASE("camera table: fov is read in each type's range, and warned about where unused",
          "[camera][table][lang]") {
  for (const CameraTypeInfo& t : cameraTypes()) {
    INFO(t.name);
    ParseResult r = parseBody("", "cameras.xml", cameraWith(t.name, "fov=\"-5\""));
    const std::string said = messages(r);
    INFO(said);
    if (t.fov) {
      CHECK(said.find("attribute 'fov': expected " + std::string(t.fov->expected) + ", got '-5'") !=
            std::string::npos);
    } else {
      CHECK(r.diagnostics.errorCount() == 0);
      CHECK(said.find("warning: <camera>: 'fov' has no effect on cameras of type " +
                      std::string(t.name)) != std::string::npos);
      if (!t.noFov.empty()) CHECK(said.find("(" + std::string(t.noFov) + ")") != std::string::npos);
    }
  }
}

TEST_CASE("camera table: the schema declares every type and every attribute with its docs",
          "[camera][table][schema]") {
  const std::string xsd = schemaText();
  const size_t begin = xsd.find("<xs:complexType name=\"cameraType_\">");
  REQUIRE(begin != std::string::npos);
  const std::string cameraType = xsd.substr(begin, xsd.find("</xs:complexType>", begin) - begin);
  for (const CameraTypeInfo& t : cameraTypes())
    CHECK(xsd.find("<xs:enumeration value=\"" + std::string(t.name) + "\">") != std::string::npos);
  for (const CameraAttribute& a : cameraAttributes()) {
    INFO(a.info.name);
    CHECK(cameraType.find("<xs:attribute name=\"" + a.info.name + "\"") != std::string::npos);
  }
  CHECK(cameraType.find("<xs:attribute name=\"type\" type=\"cameraType\" default=\"pinhole\">") !=
        std::string::npos);
  // The common attributes show the Camera's own defaults; the others state them in words.
  CHECK(
      cameraType.find("<xs:attribute name=\"far\" type=\"distanceOrInfinity\" default=\"inf\">") !=
      std::string::npos);
  CHECK(cameraType.find("<xs:attribute name=\"pitch\" type=\"positiveNumber\">") !=
        std::string::npos);
}

TEST_CASE("camera table: check counts every type, each has a projection, the exporter its row",
          "[camera][table][povray]") {
  std::string cameras;
  for (const CameraTypeInfo& t : cameraTypes()) cameras += cameraWith(t.name);
  auto scene = parseValid("", "cameras.xml", cameras);
  const SceneCounts counts = countScene(*scene);
  for (const CameraTypeInfo& t : cameraTypes()) {
    INFO(t.name);
    CHECK(counts.cameras.at(std::string(t.name)) == 1);
    Camera camera;
    camera.type = t.type;
    CHECK(makeProjection(camera, 24, 12) != nullptr);

    Exported e = exportScene("<render width=\"120\" height=\"60\"/>" + cameraWith(t.name));
    if (t.pov.keyword.empty()) {
      CHECK_FALSE(e.pov.ok());
      CHECK(e.messages().find("<camera type=\"" + std::string(t.name) +
                              "\">: POV-Ray has no equivalent camera") != std::string::npos);
      continue;
    }
    REQUIRE(e.pov.ok());
    // A cylinder camera's keyword carries its type number (1 by default).
    const std::string argument =
        t.type == CameraType::Cylinder ? " 1" : (t.type == CameraType::Mesh ? " {" : "");
    CHECK(e.has("camera {\n  " + std::string(t.pov.keyword) + argument + "\n"));
  }
}
