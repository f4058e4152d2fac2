// The shipped material library (library/*.xml, compiled in, included as lucent:NAME.xml):
// every file loads cleanly, the ids are unique across files, and the materials are what
// their documentation says (metals reflect, glass is a Fresnel dielectric with its ior).
#include "lang/library.h"
#include "lang/parser.h"
#include "valid_scene_loading.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>

using namespace lucent;
using lucent::testing::messages;

namespace {

ParseResult parseWith(const std::string& includes) {
  return parseSceneString("<scene version=\"1\">" + includes +
                              "<camera position=\"0 0 10\"/><sphere material=\"gold\"/></scene>",
                          "library_test.xml");
}

const Material& byId(const Scene& s, const std::string& id) {
  for (const Material& m : s.materials)
    if (m.id == id) return m;
  FAIL("no material " << id);
  return s.materials[0];
}

}  // namespace

TEST_CASE("library: every file loads without a diagnostic, ids unique across files",
          "[lang][library]") {
  std::vector<std::string_view> names = libraryFileNames();
  REQUIRE(names.size() >= 4);
  std::set<std::string> ids;
  for (std::string_view name : names) {
    if (name == "materials.xml") continue;
    // Each file alone (with metals for the sphere's gold).
    ParseResult r = parseWith(
        "<include src=\"lucent:metals.xml\"/><include src=\"lucent:" + std::string(name) + "\"/>");
    INFO(name << "\n" << messages(r));
    REQUIRE(r.scene);
    CHECK(r.diagnostics.all().empty());
  }
  // All at once: no id is defined twice.
  ParseResult all = parseWith("<include src=\"lucent:materials.xml\"/>");
  INFO(messages(all));
  REQUIRE(all.scene);
  CHECK(all.diagnostics.all().empty());
  for (const Material& m : all.scene->materials)
    if (!m.id.empty() && m.id != "(default)") CHECK(ids.insert(m.id).second);
  CHECK(ids.size() >= 60);
}

TEST_CASE("library: metals reflect their colour, glass is a dielectric with its ior",
          "[lang][library]") {
  ParseResult r = parseWith("<include src=\"lucent:materials.xml\"/>");
  REQUIRE(r.scene);
  const Scene& s = *r.scene;
  const Material& gold = byId(s, "gold");
  CHECK(gold.reflective.r > gold.reflective.g);
  CHECK(gold.reflective.g > gold.reflective.b);
  CHECK(byId(s, "silver").reflective.b > 0.7f);
  for (auto [id, ior] : {std::pair{"water", 1.333},
                         {"diamond", 2.417},
                         {"glass", 1.52},
                         {"ice", 1.309},
                         {"ruby", 1.77}}) {
    const Material& m = byId(s, id);
    INFO(id);
    CHECK(m.ior == ior);
    CHECK(m.fresnel);
    CHECK(m.transmissive == Color(1.0f));
  }
  // Coloured gems colour by absorption; ruby absorbs green and blue most.
  const Material& ruby = byId(s, "ruby");
  CHECK(ruby.absorption.g > ruby.absorption.r);
  // Materials based on others inherit: red-plastic keeps plastic's highlight.
  CHECK(byId(s, "red-plastic").specular == byId(s, "plastic").specular);
  CHECK(byId(s, "frosted-glass").ior == 1.52);
}

TEST_CASE("library: woods and stones are patterns with colour maps", "[lang][library]") {
  ParseResult r = parseWith("<include src=\"lucent:materials.xml\"/>");
  REQUIRE(r.scene);
  const Scene& s = *r.scene;
  auto patternOf = [&](const std::string& id) -> const PatternTexture& {
    const Material& m = byId(s, id);
    INFO(id);
    REQUIRE(std::holds_alternative<PatternTexture>(m.texture));
    return std::get<PatternTexture>(m.texture);
  };
  for (const char* id : {"oak", "dark-oak", "pine", "cherry", "walnut", "mahogany", "birch", "teak",
                         "varnished-oak", "varnished-mahogany"}) {
    INFO(id);
    const PatternTexture& t = patternOf(id);
    CHECK(t.pattern.type == PatternType::wood);
    CHECK(t.map.entries.size() >= 2);
  }
  for (auto [id, type] : {std::pair{"granite", PatternType::granite},
                          {"rose-granite", PatternType::granite},
                          {"pink-granite", PatternType::granite},
                          {"black-granite", PatternType::granite},
                          {"white-marble", PatternType::marble},
                          {"red-marble", PatternType::marble},
                          {"green-marble", PatternType::marble},
                          {"jade", PatternType::marble},
                          {"brown-agate", PatternType::agate},
                          {"blue-agate", PatternType::agate},
                          {"sandstone", PatternType::gradient},
                          {"slate", PatternType::bozo},
                          {"pink-alabaster", PatternType::bozo}}) {
    INFO(id);
    const PatternTexture& t = patternOf(id);
    CHECK(t.pattern.type == type);
    CHECK(t.map.entries.size() >= 2);
  }
  // Jade is POV-Ray's: marble with turbulence 1.8 and a sharp edge at 0.8 of its map.
  const PatternTexture& jade = patternOf("jade");
  REQUIRE(jade.map.entries.size() == 4);
  CHECK(jade.map.entries[1].at == 0.8);
  CHECK(jade.map.entries[2].at == 0.8);
  CHECK(jade.map.entries[1].color == Color(0.0f, 0.3f, 0.0f));
  // Varnished woods keep their wood's pattern and add a sharp highlight.
  CHECK(patternOf("varnished-oak").map.entries.size() == patternOf("oak").map.entries.size());
  CHECK(byId(s, "varnished-oak").shininess == 200);
  CHECK(byId(s, "oak").shininess == 30);
}

TEST_CASE("library: lucent: files are readable whatever the file-access rules", "[lang][library]") {
  // A scene in a folder of its own may read nothing outside it, but the library is compiled in.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lucent_library_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path scene = dir / "scene.xml";
  std::ofstream(scene) << "<scene version=\"1\"><include src=\"lucent:glass.xml\"/>"
                          "<camera position=\"0 0 10\"/><sphere material=\"diamond\"/></scene>";
  ParseResult r = parseSceneFile(scene.string(), ParseOptions{});
  INFO(messages(r));
  REQUIRE(r.scene);
  CHECK(byId(*r.scene, "diamond").ior == 2.417);
  std::filesystem::remove_all(dir);
}

TEST_CASE("library: an unknown library file is an error that lists the files", "[lang][library]") {
  ParseResult r = parseWith("<include src=\"lucent:metal.xml\"/>");
  CHECK_FALSE(r.scene);
  const std::string m = messages(r);
  CHECK_THAT(m,
             Catch::Contains("the library has no file 'metal.xml' (did you mean 'metals.xml'?)"));
  CHECK_THAT(m, Catch::Contains("glass.xml"));
}
