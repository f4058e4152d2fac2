// Invalid scenes too large or too environment-dependent for data files: hostile nesting,
// long include chains, symbolic links that leave the scene's folder, unreadable files.
#include "../support/scene_text.h"
#include "../temp_dir.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;
using lucent::test::messages;
using lucent::test::TempDir;
using namespace lucent;

TEST_CASE("lang: 100,000 nested elements give an error at the first one too deep, not a crash",
          "[lang][invalid]") {
  const int n = 100000;
  std::string xml = "<scene version=\"1\">\n<camera/>\n";
  for (int i = 0; i < n; ++i) xml += "<group>";
  for (int i = 0; i < n; ++i) xml += "</group>";
  xml += "\n</scene>\n";
  ParseResult r = parseSceneString(xml, "deep.xml");
  INFO(messages(r));
  REQUIRE(r.scene == nullptr);
  REQUIRE(r.diagnostics.errorCount() == 1);
  const Diagnostic& d = r.diagnostics.all()[0];
  // The 257th <group> starts at byte 256 * 7 of line 3.
  CHECK(d.loc.line == 3);
  CHECK(d.loc.col == 256 * 7 + 1);
  CHECK_THAT(d.message, Catch::Contains("elements nest deeper than 256 levels"));
}

TEST_CASE("lang: 100,000 nested unknown elements and a long chain of <use> do not crash",
          "[lang][invalid]") {
  const int n = 100000;
  std::string xml = "<scene version=\"1\"><camera/><group>";
  for (int i = 0; i < n; ++i) xml += "<a>";
  for (int i = 0; i < n; ++i) xml += "</a>";
  xml += "</group></scene>";
  ParseResult r = parseSceneString(xml, "deep-unknown.xml");
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK_THAT(r.diagnostics.all()[0].message, Catch::Contains("unknown element <a> inside <group>"));

  // Each <use> instantiates the previous: 5000 levels through references.
  std::string chain = "<scene version=\"1\"><camera/><defs><sphere id=\"n0\"/>";
  for (int i = 1; i < 5000; ++i)
    chain += "<use id=\"n" + std::to_string(i) + "\" ref=\"n" + std::to_string(i - 1) + "\"/>";
  chain += "</defs><use ref=\"n4999\"/></scene>";
  ParseResult c = parseSceneString(chain, "chain.xml");
  INFO(messages(c));
  REQUIRE(c.scene == nullptr);
  CHECK_THAT(
      messages(c),
      Catch::Contains("nests deeper than 1024 levels, counting what its <use>s instantiate"));
}

TEST_CASE("lang: includes nest at most 16 files deep", "[lang][invalid]") {
  TempDir dir("include-depth");
  for (int i = 0; i < 20; ++i)
    dir.write("f" + std::to_string(i) + ".xml", "<scene version=\"1\">\n  <include src=\"f" +
                                                    std::to_string(i + 1) + ".xml\"/>\n</scene>\n");
  dir.write("f20.xml", "<scene version=\"1\"><sphere/></scene>\n");
  fs::path top = dir.write(
      "top.xml", "<scene version=\"1\">\n<camera/>\n<include src=\"f0.xml\"/>\n</scene>\n");
  ParseResult r = parseSceneFile(top.string());
  INFO(messages(r));
  REQUIRE(r.scene == nullptr);
  REQUIRE(r.diagnostics.errorCount() == 1);
  const Diagnostic& d = r.diagnostics.all()[0];
  // top.xml is level 1, f0 level 2, ..., f14 level 16: its include is refused.
  CHECK(d.loc.file == (dir.path / "f14.xml").string());
  CHECK(d.loc.line == 2);
  CHECK(d.loc.col == 17);
  CHECK_THAT(d.message, Catch::Contains("includes nest deeper than 16 files"));
}

TEST_CASE(
    "lang: a symbolic link that leaves the scene's folder is refused, --allow-path permits it",
    "[lang][invalid]") {
  TempDir dir("symlink");
  dir.write("outside/secret.xml", "<scene version=\"1\"><sphere id=\"secret\"/></scene>\n");
  dir.write("outside/mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  fs::create_directories(dir.path / "scene");
  fs::create_symlink(dir.path / "outside", dir.path / "scene" / "linked");
  fs::path scene = dir.write(
      "scene/main.xml",
      "<scene version=\"1\">\n<camera/>\n<include src=\"linked/secret.xml\"/>\n</scene>\n");
  ParseResult r = parseSceneFile(scene.string());
  INFO(messages(r));
  REQUIRE(r.scene == nullptr);
  REQUIRE(r.diagnostics.errorCount() == 1);
  const Diagnostic& d = r.diagnostics.all()[0];
  CHECK(d.loc.line == 3);
  CHECK(d.loc.col == 15);
  std::string resolved = fs::weakly_canonical(dir.path / "outside" / "secret.xml").string();
  CHECK_THAT(d.message, Catch::Contains("'linked/secret.xml' leads to '" + resolved +
                                        "', outside the folders"));

  ParseOptions allow;
  allow.allowPaths.push_back((dir.path / "outside").string());
  ParseResult ok = parseSceneFile(scene.string(), allow);
  INFO(messages(ok));
  REQUIRE(ok.scene != nullptr);
  REQUIRE(ok.scene->root->children.size() == 1);
  CHECK(ok.scene->root->children[0]->id == "secret");
}

TEST_CASE("lang: a missing scene file is an input/output failure, not an invalid scene",
          "[lang][invalid]") {
  TempDir dir("missing");
  ParseResult r = parseSceneFile((dir.path / "nothing.xml").string());
  CHECK(r.scene == nullptr);
  CHECK(r.ioFailure);
  REQUIRE(r.diagnostics.errorCount() == 1);
  CHECK(r.diagnostics.all()[0].str() ==
        (dir.path / "nothing.xml").string() + ": error: cannot read the scene file: no such file");

  ParseResult folder = parseSceneFile(dir.path.string());
  CHECK(folder.ioFailure);
  CHECK_THAT(folder.diagnostics.all()[0].message, Catch::Contains("it is a folder"));
}

TEST_CASE("lang: errors of several files and phases come back sorted by file, line and column",
          "[lang][invalid]") {
  TempDir dir("sorted");
  dir.write("part.xml", "<scene version=\"1\">\n  <sphere radius=\"-2\"/>\n</scene>\n");
  fs::path top = dir.write("top.xml",
                           "<scene version=\"1\">\n"
                           "  <camera/>\n"
                           "  <use ref=\"nothing\"/>\n"           // reported in the last phase
                           "  <material id=\"m\" ior=\"-1\"/>\n"  // reported in the material phase
                           "  <include src=\"part.xml\"/>\n"
                           "  <box material=\"m\" min=\"2 2 2\"/>\n"
                           "</scene>\n");
  ParseResult r = parseSceneFile(top.string());
  REQUIRE(r.diagnostics.errorCount() == 4);
  const auto& d = r.diagnostics.all();
  CHECK(d[0].loc.file == top.string());
  CHECK(d[0].loc.line == 3);
  CHECK(d[1].loc.line == 4);
  CHECK(d[2].loc.line == 6);
  CHECK(d[3].loc.file == (dir.path / "part.xml").string());
  CHECK(d[3].loc.line == 2);
}

TEST_CASE("lang: hostile inputs never crash the parser", "[lang][invalid]") {
  // Truncations of a valid scene at every byte: each is refused with a located error and
  // never crashes (the root element is then unclosed, so no cut is a whole document).
  std::string scene =
      "<scene version=\"1\"><param name=\"r\" value=\"2\"/><camera fov=\"${r}0\"/>"
      "<defs><group id=\"g\"><sphere radius=\"${r}\"/></group></defs>"
      "<difference transform=\"rotate(30, 1 1 0) scale(2)\"><use ref=\"g\"/><box/></difference>"
      "<mesh positions=\"0 0 0 1 0 0 0 1 0\" indices=\"0 1 2\"/></scene>";
  ParseResult whole = parseSceneString(scene, "cut.xml");
  INFO(messages(whole));
  REQUIRE(whole.scene != nullptr);
  REQUIRE(whole.diagnostics.all().empty());
  CHECK(whole.scene->cameras.at(0).fov == Approx(20.0));
  for (size_t n = 0; n < scene.size(); ++n) {
    ParseResult r = parseSceneString(scene.substr(0, n), "cut.xml");
    INFO("cut after " << n << " bytes");
    CHECK(r.scene == nullptr);
    CHECK(r.diagnostics.hasErrors());
    for (const Diagnostic& d : r.diagnostics.all()) CHECK(d.loc.file == "cut.xml");
  }
  // Binary junk and an empty document.
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 7919) % 256);
  CHECK(parseSceneString(junk, "junk.xml").diagnostics.hasErrors());
  ParseResult empty = parseSceneString("", "empty.xml");
  REQUIRE(empty.diagnostics.errorCount() == 1);
  CHECK_THAT(empty.diagnostics.all()[0].message, Catch::Contains("XML syntax error"));
}
