// What the registry (shape_registry.h) knows of one geometry element, in one place: its
// element name, its attributes with types, defaults and ranges, whether it is a solid, how
// it is built, how it is written for POV-Ray, and its statistics slot. The parser, the
// schema, `lucent check`, `--stats`, the POV-Ray exporter and the contract tests all read it.
//
// A shape's entry is written once, typed on its parameters (ShapeEntry<SphereSpec>, in
// shapes/sphere.cpp), and erased into a ShapeType for the table.
#pragma once

#include "attribute_info.h"
#include "attribute_input.h"
#include "shape_spec.h"

#include "primitives/shape.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lucent {

// A child element a shape reads itself (a blob's <component>): its name and attributes,
// for the parser's attribute check and the schema.
struct ChildElementInfo {
  std::string name;
  std::string doc;
  std::vector<AttributeInfo> attributes;
  bool required = false;  // at least one
  // The schema's particles for the child's own children, when it has any (an isosurface's
  // <pigment-function> holds a texture); the parser reads those itself.
  std::string contentXsd = {};
  // It may hold one <material> of its own instead of a material="id" attribute
  // (AttributeInput::material reads either): a blob component's.
  bool inlineMaterial = false;
};

// The <pigment-function> child of a shape whose function calls pigments (isosurface.cpp).
ChildElementInfo pigmentFunctionChild();

// The exporter's side of writing one shape (povray/pov_geometry.cpp implements it). The
// entry writes the object's keyword and the lines of its own parameters; the exporter adds
// the material and the transform and closes the object.
class PovShapeOut {
 public:
  virtual ~PovShapeOut() = default;
  virtual void open(std::string_view keyword) = 0;  // "sphere {"
  virtual void line(std::string_view text) = 0;
  virtual std::string number(double v) const = 0;       // POV-Ray's number syntax
  virtual std::string vector(const Vec3& v) const = 0;  // <x, y, z>
  // The identifier of a mesh2 declared once for this mesh data (the exporter writes it).
  virtual std::string declaredMesh(const MeshSpec& mesh) = 0;
  // An expression of the scene language as a POV-Ray function body with `constants` (the
  // names other than x, y and z) written as their numbers; nullopt with `problem` set for
  // what POV-Ray cannot express (random()). The pigment functions it calls are declared
  // first (before the shape's block opens).
  virtual std::optional<std::string> function(
      const std::string& text, const std::vector<std::pair<std::string, double>>& constants,
      const std::vector<std::shared_ptr<const PigmentFunction>>& pigments,
      std::string& problem) = 0;
  // What the shape's parameters cannot be written as (an isosurface's random()): an
  // export error at the shape.
  virtual void error(const std::string& message) = 0;
  // A scene material as POV-Ray's texture of a part of the shape (a blob component's):
  // "texture { NAME }" of the declared texture (an error when the material depends on the
  // shape, an image map or a uv mapping).
  virtual std::string materialTexture(uint32_t material) = 0;
};

// How a surface point becomes an image texture's (u, v), as POV-Ray's image_map can
// reproduce it (povray/pov_image_map.h writes it).
struct ImageMapping {
  enum Kind { None, Planar, Spherical, MeshUV } kind = None;
  // Planar: the affine map from the shape's object space to (u, v, w); u and v are Lucent's
  // coordinates, w anything that keeps the map invertible.
  Mat4 uvFromObject{1.0};
  Vec3 center{0.0};  // spherical: the sphere's centre
  // POV-Ray's uv_mapping reads u the other way here (1 - u): it takes the angle about y in
  // its left-handed space, Lucent's mapped (u, v) in the importer's (z negated), so the
  // export writes uv-mapped placements through that mirror (sphere, torus, lathe, sor).
  bool uvMirrored = false;
};
// A face that takes its own copy of an image (a box's six faces): a POV-Ray plane, inside
// towards the shape, with the face's mapping.
struct ImageMapFace {
  Vec3 normal{0.0};
  double offset = 0.0;
  ImageMapping mapping;
};
// The affine matrix whose rows are u, v and w (and 0 0 0 1).
inline Mat4 rowsMatrix(const Vec4& u, const Vec4& v, const Vec4& w) {
  return glm::transpose(Mat4(u, v, w, Vec4(0.0, 0.0, 0.0, 1.0)));
}

// One attribute of a shape element: what the schema and the attribute check need, and how
// the generic reader stores it into the parameters (null for attributes the entry's
// finish() reads itself).
template <class S>
struct Field {
  AttributeInfo info;
  std::function<void(S&, AttributeInput&)> read;

  Field doc(std::string text) && {
    info.doc = std::move(text);
    return std::move(*this);
  }
};

template <class S>
struct ShapeEntry {
  using Build = std::function<std::shared_ptr<const Shape>(const S&)>;
  using WritePov = std::function<void(const S&, PovShapeOut&)>;

  // The element, the POV-Ray writer and the builder are required: an entry cannot be made
  // without them.
  ShapeEntry(const char* element, const char* plural, Build build, WritePov pov)
      : element(element), plural(plural), build(std::move(build)), pov(std::move(pov)) {}

  const char* element;   // "sphere"
  const char* plural;    // "spheres", for --stats
  const char* doc = "";  // one sentence for the schema: "A sphere (solid)."
  std::vector<Field<S>> fields;
  // Child elements the entry's finish() reads (AttributeInput::forEachChild); most have none.
  std::vector<ChildElementInfo> children;
  // After the fields are read: checks between attributes, loading; may be empty.
  std::function<void(S&, AttributeInput&)> finish;
  // "" when the parameters make a solid, else why not ("it is open").
  std::function<std::string(const S&)> notSolid = [](const S&) { return std::string(); };
  Build build;
  WritePov pov;
  std::function<long long(const S&)> triangles = [](const S&) { return 0LL; };
  // How POV-Ray's image_map reproduces the shape's (u, v): one mapping for the whole shape
  // or, when povImageFaces gives any, one per face; with neither an image texture on the
  // shape cannot be exported (an error that names the shape).
  std::function<ImageMapping(const S&)> povImageMapping = [](const S&) { return ImageMapping{}; };
  std::function<std::vector<ImageMapFace>(const S&)> povImageFaces = [](const S&) {
    return std::vector<ImageMapFace>{};
  };
  // Valid parameters that show the shape's cases (the contract tests run every one);
  // made on demand, so a render never pays for them.
  std::function<std::vector<std::pair<std::string, S>>()> samples;
};

// The helpers entries declare their fields with: each default is the parameters' own
// default member value, so it is written once.
std::string attributeText(double v);
std::string attributeText(const Vec3& v);

template <class S>
Field<S> numberField(const char* name, double S::*m, NumberRule rule = NumberRule::any()) {
  return {{name, AttrType::Number, rule, {}, attributeText(S{}.*m), false, "", 1},
          [name, m, rule](S& s, AttributeInput& in) { s.*m = in.number(name, s.*m, rule); }};
}
template <class S>
Field<S> vectorField(const char* name, Vec3 S::*m) {
  return {{name, AttrType::Vector, {}, {}, attributeText(S{}.*m), false, "", 1},
          [name, m](S& s, AttributeInput& in) { s.*m = in.vector(name, s.*m); }};
}
template <class S>
Field<S> directionField(const char* name, Vec3 S::*m) {
  return {{name, AttrType::Direction, {}, {}, attributeText(S{}.*m), false, "", 1},
          [name, m](S& s, AttributeInput& in) { s.*m = in.direction(name, s.*m); }};
}
template <class S>
Field<S> booleanField(const char* name, bool S::*m) {
  return {{name, AttrType::Boolean, {}, {}, S{}.*m ? "true" : "false", false, "", 1},
          [name, m](S& s, AttributeInput& in) { s.*m = in.boolean(name, s.*m); }};
}
// An attribute the entry's finish() reads itself (type and default for the schema only).
template <class S>
Field<S> readByEntry(const char* name, AttrType type, std::string defaultText = "",
                     std::vector<std::string_view> choices = {}, int listArity = 1) {
  return {{name, type, {}, std::move(choices), std::move(defaultText), false, "", listArity},
          nullptr};
}

// The registry's view of a shape, whatever its parameter type.
struct ShapeType {
  std::string element;
  std::string plural;
  std::string doc;
  size_t slot = 0;  // the index in the registry: ShapeSpec's alternative, --stats' slot
  std::vector<AttributeInfo> attributes;
  std::vector<ChildElementInfo> children;
  std::function<ShapeSpec(AttributeInput&)> read;
  std::function<std::string(const ShapeSpec&)> notSolid;
  std::function<std::shared_ptr<const Shape>(const ShapeSpec&)> build;
  std::function<void(const ShapeSpec&, PovShapeOut&)> writePov;
  std::function<long long(const ShapeSpec&)> triangles;
  std::function<ImageMapping(const ShapeSpec&)> povImageMapping;
  std::function<std::vector<ImageMapFace>(const ShapeSpec&)> povImageFaces;
  std::function<std::vector<std::pair<std::string, ShapeSpec>>()> samples;

  std::vector<std::string_view> attributeNames() const;
  const ChildElementInfo* child(std::string_view name) const;
};

// Each shape's entry, defined in its own file under shapes/. A ShapeSpec alternative
// without one fails to link.
template <class S>
ShapeEntry<S> shapeEntry();

template <class S>
ShapeType eraseShapeEntry(ShapeEntry<S> e, size_t slot) {
  ShapeType t;
  t.element = e.element;
  t.plural = e.plural;
  t.doc = e.doc;
  t.slot = slot;
  for (const Field<S>& f : e.fields) t.attributes.push_back(f.info);
  t.children = e.children;
  t.read = [fields = e.fields, finish = e.finish](AttributeInput& in) -> ShapeSpec {
    S s{};
    for (const Field<S>& f : fields)
      if (f.read) f.read(s, in);
    if (finish) finish(s, in);
    return s;
  };
  t.notSolid = [f = e.notSolid](const ShapeSpec& s) { return f(std::get<S>(s)); };
  t.build = [f = e.build](const ShapeSpec& s) { return f(std::get<S>(s)); };
  t.writePov = [f = e.pov](const ShapeSpec& s, PovShapeOut& out) { f(std::get<S>(s), out); };
  t.triangles = [f = e.triangles](const ShapeSpec& s) { return f(std::get<S>(s)); };
  t.povImageMapping = [f = e.povImageMapping](const ShapeSpec& s) { return f(std::get<S>(s)); };
  t.povImageFaces = [f = e.povImageFaces](const ShapeSpec& s) { return f(std::get<S>(s)); };
  t.samples = [f = e.samples] {
    std::vector<std::pair<std::string, ShapeSpec>> out;
    if (f)
      for (auto& [name, s] : f()) out.emplace_back(name, ShapeSpec(std::move(s)));
    return out;
  };
  return t;
}

}  // namespace lucent
