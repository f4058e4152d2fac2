// The scene writer's text under construction (scene_writer*.cpp): elements with their
// attributes, indented, each object preceded by a comment naming where it came from.
#pragma once

#include "scenegraph/located_error.h"
#include "scenegraph/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace lucent {

using Attributes = std::vector<std::pair<std::string, std::string>>;

class XmlOut {
 public:
  std::string text;
  int depth = 1;

  // "<!-- from file:line -->" before an object.
  void source(const SourceLoc& loc);
  // <name a="..."/> when `empty`, else <name a="..."> (close it with close(name)).
  void open(const std::string& name, const Attributes& attributes, bool empty);
  void close(const std::string& name);
};

// What the writer cannot write: an error at the construct.
[[noreturn]] void cannotWrite(const SourceLoc& loc, const std::string& what);

// A file reference as the written scene reads it: relative to the output's folder.
std::string fileReference(const std::string& resolvedPath, const std::string& folder);

// The material's attributes and children (finish table, textures, normal, bump map), inside
// an element the caller opened as <material ...>; returns the attributes, writes the
// children into `out` through `children`.
Attributes materialAttributes(const Material& m);
void writeMaterialChildren(const Material& m, XmlOut& out, const std::string& folder);
void writePatternTexture(const PatternTexture& t, const SourceLoc& loc, XmlOut& out);

}  // namespace lucent
