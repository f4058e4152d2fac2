// <camera type="mesh"> with its <mesh> children (render/mesh_camera.h): read as written (the
// faces in order, no repair), written back and read again the same, exported as POV-Ray's
// mesh_camera block (each face written a, c, b so POV-Ray's normal is Lucent's), and the
// errors of a camera POV-Ray would refuse.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// Two faces sharing an edge but written against each other (a mesh's loading would turn
// one over): the camera keeps both as written.
const char* kCamera = R"XML(<camera type="mesh" distribution="0" rays-per-pixel="2" offset="0.25"
      reverse="true" far="40">
    <mesh positions="0 0 0  1 0 0  0 1 0  1 1 0" indices="0 1 2  1 2 3"/>
    <mesh positions="0 0 0  1 0 0  0 1 0" indices="0 1 2" uvs="0 0  1 0  0 1"
          transform="translate(0 0 2)"/>
  </camera>)XML";

}  // namespace

TEST_CASE("mesh camera: read as written then written back and read again the same",
          "[lang][camera][mesh-camera]") {
  auto scene = parseClean("<sphere/>", "test.xml", kCamera);
  const Camera& c = scene->cameras.front();
  CHECK(c.type == CameraType::Mesh);
  CHECK(c.raysPerPixel == 2);
  CHECK(c.distribution == 0);
  CHECK(c.offset == 0.25);
  CHECK(c.reverse);
  CHECK(c.far == 40.0);
  REQUIRE(c.meshes.size() == 2);
  REQUIRE(c.meshes[0].data);
  CHECK(c.meshes[0].data->triangles.size() == 2);
  CHECK(c.meshes[0].data->triangles[1] == std::array<uint32_t, 3>{1, 2, 3});  // not turned
  CHECK(c.meshes[1].data->uvs.size() == 3);
  CHECK(c.meshes[1].transform[3][2] == 2.0);
  const std::string text = writeSceneXml(*scene, WriteOptions{});
  INFO(text);
  ParseResult again = parseSceneString(text, "again.xml");
  INFO(messages(again));
  REQUIRE(again.scene);
  const Camera& back = again.scene->cameras.front();
  CHECK(back.type == CameraType::Mesh);
  CHECK(back.raysPerPixel == 2);
  CHECK(back.offset == 0.25);
  CHECK(back.reverse);
  CHECK(back.far == 40.0);
  REQUIRE(back.meshes.size() == 2);
  CHECK(back.meshes[0].data->positions == c.meshes[0].data->positions);
  CHECK(back.meshes[0].data->triangles == c.meshes[0].data->triangles);
  CHECK(back.meshes[1].data->uvs == c.meshes[1].data->uvs);
  CHECK(back.meshes[1].transform == c.meshes[1].transform);
}

TEST_CASE("mesh camera exported as POV-Ray's mesh_camera block", "[lang][camera][povray]") {
  auto scene = parseClean("<sphere/>", "test.xml", kCamera);
  const PovExport exported = exportPov(*scene);
  INFO(exported.text);
  REQUIRE(exported.ok());
  const size_t camera = exported.text.find("camera {\n  mesh_camera {\n    2 0 40\n");
  REQUIRE(camera != std::string::npos);
  // a, c, b: POV-Ray's (P3 − P1) × (P2 − P1) is then Lucent's (b − a) × (c − a).
  CHECK(exported.text.find("triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> }", camera) !=
        std::string::npos);
  CHECK(exported.text.find("triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }", camera) !=
        std::string::npos);
  CHECK(exported.text.find("uv_vectors <0, 0>, <0, 1>, <1, 0>", camera) != std::string::npos);
  CHECK(exported.text.find("location <0, 0, 0.25>", camera) != std::string::npos);
  CHECK(exported.text.find("direction <0, 0, -1>", camera) != std::string::npos);
}

TEST_CASE("mesh camera: what POV-Ray refuses is an error at its place",
          "[lang][camera][mesh-camera]") {
  auto firstError = [](const std::string& camera) {
    ParseResult r = parseBody("<sphere/>", "test.xml", camera);
    CHECK_FALSE(r.scene);
    return r.diagnostics.all().empty() ? std::string() : r.diagnostics.all().front().str();
  };
  const std::string face = R"(<mesh positions="0 0 0 1 0 0 0 1 0" indices="0 1 2"/>)";
  CHECK(firstError(R"(<camera type="mesh"/>)") ==
        "test.xml:1:20: error: a mesh camera needs at least one <mesh> child (the faces its "
        "rays start on)");
  CHECK(firstError(R"(<camera type="mesh" rays-per-pixel="2">)" + face + "</camera>") ==
        "test.xml:1:56: error: <camera> attribute 'rays-per-pixel': a mesh camera of "
        "distribution 0 takes ray r of each sample from mesh r: rays-per-pixel (2) must not "
        "exceed its 1 meshes");
  CHECK(firstError(R"(<camera type="mesh" distribution="2" rays-per-pixel="2">)" + face +
                   "</camera>") ==
        "test.xml:1:73: error: <camera> attribute 'rays-per-pixel': a mesh camera of "
        "distribution 2 takes one ray per pixel (as POV-Ray: its rays would be the same)");
  CHECK(firstError(R"(<camera type="mesh" smooth="true">)" + face + "</camera>")
            .find("smooth is for a mesh camera of distribution 3") != std::string::npos);
  CHECK(firstError(R"(<camera type="mesh"><normal type="bumps"/>)" + face + "</camera>")
            .find("a mesh camera takes <mesh> children") != std::string::npos);
  CHECK(firstError(R"(<camera type="mesh"><mesh src="a.obj"/></camera>)")
            .find("a mesh camera's <mesh> needs inline 'positions' and 'indices'") !=
        std::string::npos);
  CHECK(firstError(R"(<camera type="mesh" distribution="4">)" + face + "</camera>")
            .find("distribution") != std::string::npos);
}

TEST_CASE("mesh camera: faces-of shares an earlier mesh's faces and is written back so",
          "[lang][camera][mesh-camera]") {
  auto scene = parseClean("<sphere/>", "test.xml",
                          R"XML(<camera type="mesh" rays-per-pixel="2">
    <mesh positions="0 0 0  1 0 0  0 1 0" indices="0 1 2"/>
    <mesh faces-of="0" transform="translate(0.5 0 0)"/>
  </camera>)XML");
  const Camera& c = scene->cameras.front();
  REQUIRE(c.meshes.size() == 2);
  CHECK(c.meshes[1].data == c.meshes[0].data);
  CHECK(c.meshes[1].transform[3][0] == 0.5);
  const std::string text = writeSceneXml(*scene, WriteOptions{});
  INFO(text);
  CHECK(text.find("faces-of=\"0\"") != std::string::npos);
  CHECK(text.find("positions=") == text.rfind("positions="));  // written once
  ParseResult again = parseSceneString(text, "again.xml");
  REQUIRE(again.scene);
  CHECK(again.scene->cameras.front().meshes[1].data == again.scene->cameras.front().meshes[0].data);
  // Errors: no earlier mesh, one out of range, lists beside it.
  const auto error = [](const std::string& meshes) {
    ParseResult r =
        parseBody("<sphere/>", "test.xml", "<camera type=\"mesh\">" + meshes + "</camera>");
    CHECK_FALSE(r.scene);
    return messages(r);
  };
  CHECK(error(R"(<mesh faces-of="0"/>)").find("this is the first") != std::string::npos);
  CHECK(error(R"(<mesh positions="0 0 0 1 0 0 0 1 0" indices="0 1 2"/><mesh faces-of="1"/>)")
            .find("faces-of") != std::string::npos);
  CHECK(error(R"(<mesh positions="0 0 0 1 0 0 0 1 0" indices="0 1 2"/>)"
              R"(<mesh faces-of="0" indices="0 1 2"/>)")
            .find("no lists of its own") != std::string::npos);
}
