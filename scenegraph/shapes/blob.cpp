// <blob threshold="1"> with <component type="sphere" center radius strength/> and
// <component type="cylinder" base cap radius strength/> children, each with an optional
// transform of its own: POV-Ray's blob
// (primitives/blob.h). POV-Ray takes a threshold of any sign; Lucent wants it > 0, since
// otherwise all of space far from the components would be inside.
#include "scenegraph/shape_type.h"

#include "primitives/blob.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

const std::vector<std::string_view> kComponentTypes{"sphere", "cylinder"};

void readComponent(BlobSpec& s, AttributeInput& c) {
  if (!c.has("type")) {
    c.error("<component> needs a 'type': sphere or cylinder");
    return;
  }
  BlobComponent comp;
  comp.kind =
      c.choice("type", 0, kComponentTypes) == 1 ? BlobComponent::Cylinder : BlobComponent::Sphere;
  if (!c.has("radius")) c.error("<component> needs a 'radius' (a number > 0)");
  comp.radius = c.number("radius", 1.0, NumberRule::positive());
  comp.strength = c.number("strength", 1.0, NumberRule::any());
  bool sphere = comp.kind == BlobComponent::Sphere;
  for (const char* a :
       sphere ? std::vector<const char*>{"base", "cap"} : std::vector<const char*>{"center"})
    if (c.has(a))
      c.attrError(
          a, sphere ? "a sphere component has a 'center'; 'base' and 'cap' belong to a cylinder"
                    : "a cylinder component has 'base' and 'cap'; 'center' belongs to a sphere");
  if (sphere) {
    comp.a = c.vector("center", Vec3(0.0));
  } else {
    comp.a = c.vector("base", Vec3(0.0));
    comp.b = c.vector("cap", Vec3(0.0, 1.0, 0.0));
    if (comp.a == comp.b) c.error("a cylinder <component> needs different 'base' and 'cap'");
  }
  comp.transform = c.transform("transform", Mat4(1.0));
  const std::optional<uint32_t> material = c.material("material");
  const Mat3 linear(comp.transform);
  double size = 0.0;
  for (int i = 0; i < 3; ++i) size = std::max(size, glm::length(linear[i]));
  if (!(std::abs(glm::determinant(linear)) > 1e-12 * size * size * size))
    c.attrError("transform", "a component's transform must be invertible (no scale of 0)");
  if (c.failed()) return;
  s.components.push_back(comp);
  // One entry per component once any has a material (POV-Ray's multi-textured blob).
  if (material || !s.componentMaterials.empty()) {
    s.componentMaterials.resize(s.components.size() - 1);
    s.componentMaterials.push_back(material);
  }
}

AttributeInfo childAttribute(const char* name, AttrType type, std::string def, std::string doc,
                             bool required = false, std::vector<std::string_view> choices = {}) {
  AttributeInfo a{name, type, {}, std::move(choices), std::move(def), required, std::move(doc)};
  if (std::string_view(name) == "radius") a.rule = NumberRule::positive();
  return a;
}

// A component's own material, by id or as one inline <material> child: POV-Ray's texture
// in a blob component.
AttributeInfo materialAttribute() {
  AttributeInfo a = childAttribute(
      "material", AttrType::Text, "",
      "The id of a top-level material of the component's own (or one inline <material> child), "
      "in the blob's space: at a hit, each component's material (the blob's where it has none) "
      "weighted by its |field| there.");
  a.schemaType = "name";
  return a;
}

// A component's own transform: its field is the one above in the component's space, as
// POV-Ray's transformed components (a sphere scaled unevenly is an ellipsoid).
AttributeInfo transformAttribute() {
  AttributeInfo a = childAttribute(
      "transform", AttrType::Text, "",
      "From the component's space to the blob's (an uneven scale makes an ellipsoid).");
  a.schemaType = "transform";
  return a;
}

}  // namespace

template <>
ShapeEntry<BlobSpec> shapeEntry<BlobSpec>() {
  ShapeEntry<BlobSpec> e(
      "blob", "blobs",
      [](const BlobSpec& s) { return std::make_shared<Blob>(s.threshold, s.components); },
      [](const BlobSpec& s, PovShapeOut& out) {
        out.open("blob");
        out.line("threshold " + out.number(s.threshold));
        for (size_t k = 0; k < s.components.size(); ++k) {
          const BlobComponent& c = s.components[k];
          // POV-Ray's matrix multiplies row vectors: its 12 numbers are the columns of
          // Lucent's (column-vector) matrix, each cut to x, y, z.
          std::string placed;
          if (c.transform != Mat4(1.0)) {
            placed = " matrix <";
            for (int col = 0; col < 4; ++col)
              for (int row = 0; row < 3; ++row)
                placed += (col || row ? ", " : "") + out.number(c.transform[col][row]);
            placed += ">";
          }
          // A component's material after its transform: it lies in the blob's space.
          if (k < s.componentMaterials.size() && s.componentMaterials[k])
            placed += " " + out.materialTexture(*s.componentMaterials[k]);
          if (c.kind == BlobComponent::Sphere)
            out.line(fmt::format("sphere {{ {}, {}, strength {}{} }}", out.vector(c.a),
                                 out.number(c.radius), out.number(c.strength), placed));
          else
            out.line(fmt::format("cylinder {{ {}, {}, {}, strength {}{} }}", out.vector(c.a),
                                 out.vector(c.b), out.number(c.radius), out.number(c.strength),
                                 placed));
        }
      });
  e.doc =
      "POV-Ray's blob: the solid where the summed field of its <component> children exceeds the "
      "threshold.";
  e.fields = {numberField("threshold", &BlobSpec::threshold, NumberRule::positive())
                  .doc("The field value at the surface; inside, the field is above it.")};
  e.children = {
      {"component",
       "One field component: strength·(1 − (r/radius)²)² within its radius, r the distance to a "
       "sphere's "
       "centre or to a cylinder's segment from base to cap.",
       {childAttribute("type", AttrType::Choice, "", "sphere or cylinder.", true, kComponentTypes),
        childAttribute("center", AttrType::Vector, "0 0 0", "A sphere's centre."),
        childAttribute("base", AttrType::Vector, "0 0 0", "A cylinder's first end."),
        childAttribute("cap", AttrType::Vector, "0 1 0", "A cylinder's second end."),
        childAttribute("radius", AttrType::Number, "", "Where the component's field ends (> 0).",
                       true),
        childAttribute("strength", AttrType::Number, "1",
                       "The field at the centre or axis; may be negative."),
        transformAttribute(), materialAttribute()},
       true}};
  e.children[0].inlineMaterial = true;
  e.finish = [](BlobSpec& s, AttributeInput& in) {
    in.forEachChild("component", [&](AttributeInput& c) { readComponent(s, c); });
    if (s.components.empty() && !in.failed())
      in.error("<blob> needs at least one <component type=\"sphere\" or \"cylinder\" .../>");
  };
  e.samples = [] {
    using C = BlobComponent;
    return std::vector<std::pair<std::string, BlobSpec>>{
        {"single sphere blob", {1.0, {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.0, 2.0}}}},
        {"two merging spheres blob",
         {0.6,
          {{C::Sphere, Vec3(-0.5, 0, 0), Vec3(0.0), 1.0, 1.0},
           {C::Sphere, Vec3(0.5, 0, 0), Vec3(0.0), 1.0, 1.0}}}},
        {"blob with a negative sphere",
         {0.5,
          {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.2, 2.0},
           {C::Sphere, Vec3(0.0, 0.7, 0.0), Vec3(0.0), 0.6, -3.0}}}}};
  };
  return e;
}

}  // namespace lucent
