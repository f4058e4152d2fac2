// Scenes for the exporter tests: written as XML (the way users write them), parsed, and
// exported; helpers to look for exact lines in the POV-Ray text.
#pragma once

#include "lang/parser.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

#include <string>

namespace lucent::test {

// A scene from the children of <scene>; a camera is added unless `body` has one.
inline std::unique_ptr<Scene> parseScene(const std::string& body) {
  std::string xml = "<scene version=\"1\">\n";
  if (body.find("<camera") == std::string::npos) xml += "<camera position=\"0 1 5\"/>\n";
  xml += body + "\n</scene>\n";
  ParseResult parsed = parseSceneString(xml, "test.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  return std::move(parsed.scene);
}

struct Exported {
  std::unique_ptr<Scene> scene;
  PovExport pov;

  bool has(const std::string& line) const { return pov.text.find(line) != std::string::npos; }
  // The messages, one a line, for INFO and for exact checks.
  std::string messages() const {
    std::string all;
    for (const PovIssue& i : pov.issues) all += i.str() + "\n";
    return all;
  }
};

inline Exported exportScene(const std::string& body) {
  Exported e;
  e.scene = parseScene(body);
  e.pov = exportPov(*e.scene);
  UNSCOPED_INFO(e.messages());
  UNSCOPED_INFO(e.pov.text);
  return e;
}

// How many times `word` stands in `text` (overlapping counted).
inline size_t occurrences(const std::string& text, const std::string& word) {
  size_t n = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

}  // namespace lucent::test
