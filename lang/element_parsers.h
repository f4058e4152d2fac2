// The parsers of the scene language's elements, one file per concept; parser.cpp calls
// them in phases (parameters, materials, everything else, then references).
#pragma once

#include "element_reader.h"
#include "parse_context.h"

#include <memory>
#include <optional>
#include <string_view>

namespace lucent {

// <render>, <camera> (render_parser.cpp, camera_parser.cpp).
void parseRender(ElementReader& r);
void parseCamera(ElementReader& r);
// light_parser.cpp: a <light>, wherever it stands, as a node (parseGeometryNode reads
// lights too, through it). Null if too deep or over the expansion limit (reported).
std::unique_ptr<Node> parseLightNode(ParseContext& ctx, const SourceFile& file,
                                     pugi::xml_node element, int depth);
// fog_parser.cpp: a <fog> (any number; all apply).
void parseFog(ElementReader& r);
void parseRainbow(ElementReader& r);

// material_parser.cpp. A top-level <material id> is registered under its id; an inline one
// (a child of a geometry node) is added without a name. Both return its index.
// The named-materials phase: every top-level <material>, each after the material its
// base= names (forward references allowed; a cycle is an error).
void parseNamedMaterials(ParseContext& ctx, const std::vector<TopLevelItem>& items);
std::optional<uint32_t> parseInlineMaterial(ElementReader& r);
// <sky> (top level, at most one).
void parseSky(ElementReader& r);
// The index of the material named by a material="id" attribute, with did-you-mean.
std::optional<uint32_t> lookupMaterial(ElementReader& r, const char* attr);

// geometry_parser.cpp: every geometry element, groups, CSG operations and <use>, and the
// lights among them.
bool isGeometryElement(std::string_view name);
const std::vector<std::string_view>& geometryElementNames();
// Null if the element is too deep (reported). Errors inside still yield a node, marked
// broken, so the rest of the file is checked.
std::unique_ptr<Node> parseGeometryNode(ParseContext& ctx, const SourceFile& file,
                                        pugi::xml_node element, int depth);
// The geometry elements inside a <clip>, <bound> or <projected-through> (no attributes; at
// least one object), parsed into `out`.
void readObjectList(ParseContext& ctx, const SourceFile& file, pugi::xml_node element, int depth,
                    std::vector<std::unique_ptr<Node>>& out);
// <defs>: its children go to scene.defs.
void parseDefs(ElementReader& r);
// The node's id attribute, registered for <use ref> (a duplicate is an error naming the first).
void registerNodeId(ElementReader& r, Node& node);

// shape_parser.cpp: the parameters of one shape element ("sphere", ...), read through the
// shape registry. Returns nothing when the element is not a shape. Errors are reported
// through r.
bool isShapeElement(std::string_view name);
std::optional<ShapeSpec> parseShape(ElementReader& r);
// The attributes each shape element accepts besides id, transform and material.
std::vector<std::string_view> shapeAttributes(std::string_view element);

// animation_parser.cpp: the <animation> element (at most one, top level) and the built-in
// names frame, frames and clock for the frame being expanded (-D frame or -D clock win).
void readAnimation(ParseContext& ctx, const std::vector<TopLevelItem>& items, int frame);

// references.cpp: resolves <use ref>, finds reference cycles, limits the instance depth
// and checks the operands of merge, intersection and difference are solids.
void resolveReferences(ParseContext& ctx);

// Ids of nodes, materials and cameras: non-empty, no whitespace.
bool isValidId(std::string_view id);

}  // namespace lucent
