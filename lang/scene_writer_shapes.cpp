// The shape attributes and children the table's probe cannot learn (scene_writer.cpp): what
// an entry's finish() reads as a list, a text, a file, a function or child elements, or
// through a choice whose default is not the parameters' value. Each is written from the
// parameters in the syntax docs/scene-language.md gives the element, so that reading the
// file again makes the same parameters.
#include "attribute_probe.h"
#include "scene_writer_out.h"
#include "xml_numbers.h"

#include "scenegraph/pigment_function.h"
#include "scenegraph/shape_type.h"

#include <algorithm>
#include <array>
#include <filesystem>

namespace lucent {

namespace {

// A text value as an attribute: '$' starts a parameter reference, "$$" is a literal '$'.
std::string literal(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '$' ? std::string("$$") : std::string(1, c);
  return out;
}

template <class List>
std::string numberList(const List& list) {
  std::string out;
  for (double v : list) out += (out.empty() ? "" : " ") + xmlNumber(v);
  return out;
}

std::string pairList(const std::vector<Vec2>& points) {
  std::string out;
  for (const Vec2& p : points)
    out += (out.empty() ? "" : " ") + xmlNumber(p.x) + " " + xmlNumber(p.y);
  return out;
}

const char* const kSplines[] = {"linear", "quadratic", "cubic", "bezier"};

// The shapes the probe learns whole: no attributes of their own here.
template <class S>
std::optional<OwnShapeText> own(const S&, const SourceLoc&, const std::string&) {
  return std::nullopt;
}

std::optional<OwnShapeText> own(const TriangleSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  if (s.normals) {
    const char* names[] = {"na", "nb", "nc"};
    for (int i = 0; i < 3; ++i) t.attributes.emplace_back(names[i], xmlVector((*s.normals)[i]));
  } else {
    t.handled = {"na", "nb", "nc"};  // a flat triangle has none
  }
  return t;
}

std::optional<OwnShapeText> own(const MeshSpec& s, const SourceLoc& loc,
                                const std::string& folder) {
  OwnShapeText t;
  static const char* smooth[] = {"auto", "true", "false"};
  if (!s.src.empty()) {
    // src as written, relative to the file that wrote it.
    const auto from = std::filesystem::path(loc.file).parent_path() / s.src;
    t.attributes.emplace_back("src", literal(fileReference(from.string(), folder)));
  } else {
    // Inline: the lists as loading left them (triangulated, oriented), which read again
    // make the same data.
    if (!s.data) cannotWrite(loc, "a <mesh> without data cannot be written");
    appendMeshLists(*s.data, t.attributes);
  }
  t.attributes.emplace_back("smooth", smooth[static_cast<int>(s.smooth)]);
  return t;
}

std::optional<OwnShapeText> own(const PolySpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  t.attributes = {{"order", std::to_string(s.order)}, {"coefficients", numberList(s.coefficients)}};
  return t;
}

std::optional<OwnShapeText> own(const PrismSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  t.attributes = {{"points", pairList(s.points)},
                  {"spline", kSplines[static_cast<int>(s.spline)]},
                  {"sweep", s.conic ? "conic" : "linear"}};
  return t;
}

// Points as x y z triples, separated by commas (as docs/scene-language.md writes them).
template <class List>
std::string tripleList(const List& points) {
  std::string out;
  for (const Vec3& p : points) out += (out.empty() ? "" : ", ") + xmlVector(p);
  return out;
}

std::optional<OwnShapeText> own(const PolygonSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  t.attributes = {{"points", tripleList(s.points)}};
  return t;
}

std::optional<OwnShapeText> own(const BicubicPatchSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  t.attributes = {{"points", tripleList(*s.points)},
                  {"type", std::to_string(s.type)},
                  {"flatness-space", s.flatnessInWorld ? "world" : "object"},
                  {"u-steps", std::to_string(s.uSteps)},
                  {"v-steps", std::to_string(s.vSteps)}};
  if (s.uvVectors != kPatchOwnUv)
    t.attributes.emplace_back("uv-vectors",
                              pairList(std::vector<Vec2>(s.uvVectors.begin(), s.uvVectors.end())));
  return t;
}

std::optional<OwnShapeText> own(const JuliaFractalSpec& s, const SourceLoc&, const std::string&) {
  static const char* const kAlgebras[] = {"quaternion", "hypercomplex"};
  static const char* const kFunctions[] = {"sqr",   "cube", "reciprocal", "exp",  "ln",    "sin",
                                           "asin",  "cos",  "acos",       "tan",  "atan",  "sinh",
                                           "asinh", "cosh", "acosh",      "tanh", "atanh", "pwr"};
  OwnShapeText t;
  t.attributes = {
      {"c", numberList(std::array<double, 4>{s.c.x, s.c.y, s.c.z, s.c.w})},
      {"algebra", kAlgebras[static_cast<size_t>(s.algebra)]},
      {"function", kFunctions[static_cast<size_t>(s.function)]},
      {"max-iteration", std::to_string(s.maxIteration)},
      {"slice", numberList(std::array<double, 4>{s.slice.x, s.slice.y, s.slice.z, s.slice.w})}};
  if (s.function == JuliaFunction::Pwr)
    t.attributes.push_back(
        {"exponent", numberList(std::array<double, 2>{s.exponent.x, s.exponent.y})});
  return t;
}

std::optional<OwnShapeText> own(const SphereSweepSpec& s, const SourceLoc&, const std::string&) {
  static const char* const kSweepSplines[] = {"linear", "cubic", "b-spline"};
  OwnShapeText t;
  std::string spheres;
  for (const SweepSphere& sp : s.spheres)
    spheres += (spheres.empty() ? "" : ", ") + xmlVector(sp.center) + " " + xmlNumber(sp.radius);
  t.attributes = {{"spheres", spheres}, {"spline", kSweepSplines[static_cast<size_t>(s.spline)]}};
  return t;
}

std::optional<OwnShapeText> own(const LatheSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  t.attributes = {{"points", pairList(s.points)}, {"spline", kSplines[static_cast<int>(s.spline)]}};
  return t;
}

std::optional<OwnShapeText> own(const SorSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  t.attributes = {{"points", pairList(s.points)}};
  return t;
}

std::optional<OwnShapeText> own(const BlobSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  for (const BlobComponent& c : s.components) {
    Attributes a;
    if (c.kind == BlobComponent::Sphere) {
      a = {{"type", "sphere"}, {"center", xmlVector(c.a)}};
    } else {
      a = {{"type", "cylinder"}, {"base", xmlVector(c.a)}, {"cap", xmlVector(c.b)}};
    }
    a.emplace_back("radius", xmlNumber(c.radius));
    a.emplace_back("strength", xmlNumber(c.strength));
    if (c.transform != Mat4(1.0)) a.emplace_back("transform", xmlMatrix(c.transform));
    t.children.push_back({"component", std::move(a)});
  }
  t.handled.push_back("<component>");
  return t;
}

// The function as read, its names other than x, y and z as local <param>s of the shape
// (the language's way of giving them), each the number it stood for.
void addFunction(OwnShapeText& t, const std::string& function,
                 const std::vector<std::pair<std::string, double>>& constants,
                 const std::vector<std::shared_ptr<const PigmentFunction>>& pigments,
                 const SourceLoc& loc) {
  for (const auto& [name, value] : constants)
    t.children.push_back({"param", {{"name", name}, {"value", xmlNumber(value)}}});
  t.attributes.emplace_back("function", literal(function));
  for (const auto& p : pigments)
    t.children.push_back(
        {"pigment-function",
         {{"name", p->name}, {"component", std::string(pigmentComponentName(p->component))}},
         [p, loc](XmlOut& out) { writeTexture(p->pigment, loc, out, ""); }});
}

// A searched shape's container (container_fields.h).
void addContainer(OwnShapeText& t, const IsosurfaceContainer& c) {
  if (c.kind == IsosurfaceContainer::Sphere) {
    t.attributes.emplace_back("container", "sphere");
    t.attributes.emplace_back("center", xmlVector(c.center));
    t.attributes.emplace_back("radius", xmlNumber(c.radius));
    t.handled = {"min", "max"};  // a box container's, refused beside a sphere
  } else {
    t.attributes.emplace_back("container", "box");
    t.attributes.emplace_back("min", xmlVector(c.min));
    t.attributes.emplace_back("max", xmlVector(c.max));
    t.handled = {"center", "radius"};  // a sphere container's
  }
}

std::optional<OwnShapeText> own(const IsosurfaceSpec& s, const SourceLoc& loc, const std::string&) {
  OwnShapeText t;
  addFunction(t, s.function, s.constants, s.pigments, loc);
  addContainer(t, s.container);
  return t;
}

std::optional<OwnShapeText> own(const ParametricSpec& s, const SourceLoc&, const std::string&) {
  OwnShapeText t;
  // The three functions' parameters, each once (the same name has the same value in all).
  std::vector<std::string> named;
  const char* const coordinates[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    for (const auto& [name, value] : s.functions->constants[i])
      if (std::find(named.begin(), named.end(), name) == named.end()) {
        named.push_back(name);
        t.children.push_back({"param", {{"name", name}, {"value", xmlNumber(value)}}});
      }
    t.attributes.emplace_back(coordinates[i], literal(s.functions->text[i]));
  }
  t.attributes.emplace_back("uv-min", xmlNumber(s.uvMin.x) + " " + xmlNumber(s.uvMin.y));
  t.attributes.emplace_back("uv-max", xmlNumber(s.uvMax.x) + " " + xmlNumber(s.uvMax.y));
  addContainer(t, s.container);
  if (s.precomputeDepth == 0) {  // the default: nothing precomputed, whatever the coordinates
    t.handled.insert(t.handled.end(), {"precompute", "precompute-coordinates"});
    return t;
  }
  t.attributes.emplace_back("precompute", std::to_string(s.precomputeDepth));
  std::string which;
  for (int i = 0; i < 3; ++i)
    if (s.precompute[i]) which += (which.empty() ? "" : " ") + std::string(coordinates[i]);
  t.attributes.emplace_back("precompute-coordinates", which);
  return t;
}

std::optional<OwnShapeText> own(const TextSpec& s, const SourceLoc&, const std::string& folder) {
  OwnShapeText t;
  t.attributes.emplace_back("string", literal(s.string));
  // The default font is no file of the scene's: left out, so that it stays the default.
  if (!s.font.empty())
    t.attributes.emplace_back("font", literal(fileReference(s.fontPath, folder)));
  t.handled.push_back("font");
  t.attributes.emplace_back("offset", xmlNumber(s.offset.x) + " " + xmlNumber(s.offset.y));
  return t;
}

std::optional<OwnShapeText> own(const HeightFieldSpec& s, const SourceLoc& loc,
                                const std::string& folder) {
  OwnShapeText t;
  if (!s.function.empty()) {
    addFunction(t, s.function, s.constants, s.pigments, loc);
    t.attributes.emplace_back(
        "resolution", std::to_string(s.resolution[0]) + " " + std::to_string(s.resolution[1]));
    t.handled.push_back("src");
    return t;
  }
  t.attributes.emplace_back("src", literal(fileReference(s.path, folder)));
  t.handled.push_back("function");
  t.handled.push_back("resolution");
  return t;
}

}  // namespace

std::optional<OwnShapeText> ownShapeText(const ShapeSpec& spec, const SourceLoc& loc,
                                         const std::string& folder) {
  return std::visit([&](const auto& s) { return own(s, loc, folder); }, spec);
}

void appendMeshLists(const MeshData& d, Attributes& attributes) {
  std::string positions, indices, normals;
  for (const Vec3& p : d.positions) positions += (positions.empty() ? "" : " ") + xmlVector(p);
  for (const auto& tri : d.triangles)
    for (uint32_t i : tri) indices += (indices.empty() ? "" : " ") + std::to_string(i);
  for (const Vec3& n : d.normals) normals += (normals.empty() ? "" : " ") + xmlVector(n);
  attributes.emplace_back("positions", positions);
  attributes.emplace_back("indices", indices);
  if (!d.normals.empty()) attributes.emplace_back("normals", normals);
  if (!d.uvs.empty()) attributes.emplace_back("uvs", pairList(d.uvs));
}

}  // namespace lucent
