// The scene writer's text under construction (scene_writer*.cpp): elements with their
// attributes, indented, each object preceded by a comment naming where it came from.
#pragma once

#include "scenegraph/located_error.h"
#include "scenegraph/scene.h"

#include <functional>
#include <optional>
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

// matrix(...) for a transform, or an error at `loc` when an entry is a nonzero number too
// small for the language to read (primitives/value_limits.h).
std::string transformText(const Mat4& m, const SourceLoc& loc);

// An inline mesh's lists as attributes: positions, indices, and normals and uvs where it has
// them (lang/scene_writer_shapes.cpp).
void appendMeshLists(const MeshData& d, Attributes& attributes);

// A file reference as the written scene reads it: relative to the output's folder.
std::string fileReference(const std::string& resolvedPath, const std::string& folder);

// The material's attributes and children (finish table, textures, normal, bump map), inside
// an element the caller opened as <material ...>; returns the attributes, writes the
// children into `out` through `children`.
// For a <layer> (`layer`): its surface terms only.
Attributes materialAttributes(const Material& m, bool layer = false);
void writeMaterialChildren(const Material& m, XmlOut& out, const std::string& folder);
void writePatternTexture(const PatternTexture& t, const SourceLoc& loc, XmlOut& out,
                         const std::string& folder);
// <pigment-function name component>TEXTURE</pigment-function>: a pigment a function calls.
void writePigmentFunction(const PigmentFunction& f, const SourceLoc& loc, XmlOut& out);
// <color-map> and its entries.
void writeColorMap(const ColorMap& map, XmlOut& out);
// <normal ...> with its children (a material's, a camera's).
void writeNormalElement(const NormalSpec& n, const SourceLoc& loc, XmlOut& out,
                        const std::string& folder);
// A texture element (<checker>, <image>, <pattern>...); file references relative to
// `folder`.
void writeTexture(const Texture& texture, const SourceLoc& loc, XmlOut& out,
                  const std::string& folder);

// What a shape entry's finish() reads that the probe cannot learn (scene_writer_shapes.cpp):
// attributes (lists, texts, files, a function, choices) and child elements (a blob's
// <component>s, an isosurface's <param>s); handled: what the entry reads that is
// written as children or left out on purpose, as the probe names it ("<component>", a text's
// default "font"). nullopt for the shapes the probe learns whole.
struct OwnShapeChild {
  std::string element;
  Attributes attributes;
  std::function<void(XmlOut&)> body{};  // its own children, if any (else written empty)
};
struct OwnShapeText {
  Attributes attributes;
  std::vector<OwnShapeChild> children;
  std::vector<std::string> handled;
};
std::optional<OwnShapeText> ownShapeText(const ShapeSpec& spec, const SourceLoc& loc,
                                         const std::string& folder);

}  // namespace lucent
