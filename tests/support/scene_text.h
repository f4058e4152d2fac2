// Scenes written inline in the tests: a <scene> around a body, parsed from a string.
#pragma once

#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <variant>

namespace lucent::test {

// Every diagnostic of a parse, one per line, as `lucent check` prints them.
inline std::string messages(const ParseResult& r) {
  std::string all;
  for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
  return all;
}

// `<scene version="1">HEAD BODY</scene>` parsed as if read from the file NAME, which its
// messages name; HEAD is a default camera unless given.
inline ParseResult parseBody(const std::string& body, const std::string& name = "test.xml",
                             const std::string& head = "<camera/>") {
  return parseSceneString("<scene version=\"1\">" + head + body + "</scene>", name);
}

// The same, required to parse without an error, or without any message at all (warnings
// included) when `clean`; the body and the messages are shown if not.
inline std::unique_ptr<Scene> parseRequired(const std::string& body, const std::string& name,
                                            const std::string& head, bool clean) {
  ParseResult r = parseBody(body, name, head);
  INFO(body << "\n" << messages(r));
  REQUIRE(r.scene);
  REQUIRE(r.diagnostics.errorCount() == 0);
  if (clean) REQUIRE(r.diagnostics.all().empty());
  return std::move(r.scene);
}
inline std::unique_ptr<Scene> parseValid(const std::string& body,
                                         const std::string& name = "test.xml",
                                         const std::string& head = "<camera/>") {
  return parseRequired(body, name, head, false);
}
inline std::unique_ptr<Scene> parseClean(const std::string& body,
                                         const std::string& name = "test.xml",
                                         const std::string& head = "<camera/>") {
  return parseRequired(body, name, head, true);
}

// The scene's material of that id (a test failure if there is none).
inline const Material& materialNamed(const Scene& s, const std::string& id) {
  for (const Material& m : s.materials)
    if (m.id == id) return m;
  FAIL("no material " << id);
  return s.materials.at(0);
}

// The pattern of the pigment of the scene's top-level node i (a test failure if it has no
// material or its texture is not a pattern).
inline const PatternSpec& nodePigmentPattern(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  const Node& n = *scene.root->children[i];
  REQUIRE(n.material);
  const auto* t = std::get_if<PatternTexture>(&scene.materials.at(*n.material).texture);
  REQUIRE(t);
  return t->pattern;
}

// A written scene's text without its comment lines (lucent convert's comments name the file
// and lines read, which differ between two writings of one scene).
inline std::string withoutComments(const std::string& text) {
  std::string out;
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(at, end - at);
    if (line.find("<!--") == std::string::npos) out += line + "\n";
    at = end + 1;
  }
  return out;
}

}  // namespace lucent::test
