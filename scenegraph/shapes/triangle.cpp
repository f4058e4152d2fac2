// <triangle a b c [na nb nc]/>: corners a, b and c (required) and optional vertex normals,
// each normalised on load; not a solid (primitives/triangle.h).
#include "scenegraph/shape_type.h"

#include "primitives/triangle.h"

#include <fmt/format.h>

namespace lucent {

namespace {
Field<TriangleSpec> corner(const char* name, Vec3 TriangleSpec::*m) {
  Field<TriangleSpec> f = vectorField(name, m);
  f.info.required = true;
  f.info.defaultText.clear();
  return f;
}
}  // namespace

template <>
ShapeEntry<TriangleSpec> shapeEntry<TriangleSpec>() {
  ShapeEntry<TriangleSpec> e(
      "triangle", "triangles",
      [](const TriangleSpec& s) { return std::make_shared<Triangle>(s.a, s.b, s.c, s.normals); },
      [](const TriangleSpec& s, PovShapeOut& out) {
        if (s.normals) {
          const auto& n = *s.normals;
          out.open("smooth_triangle");
          out.line(fmt::format("{}, {},", out.vector(s.a), out.vector(n[0])));
          out.line(fmt::format("{}, {},", out.vector(s.b), out.vector(n[1])));
          out.line(fmt::format("{}, {}", out.vector(s.c), out.vector(n[2])));
        } else {
          out.open("triangle");
          out.line(fmt::format("{}, {}, {}", out.vector(s.a), out.vector(s.b), out.vector(s.c)));
        }
      });
  e.doc = "A single triangle a, b, c (not solid).";
  e.fields = {corner("a", &TriangleSpec::a)
                  .doc("First vertex. Seen from the front the vertices a, b, c run "
                       "counter-clockwise (normal = (b−a)×(c−a))."),
              corner("b", &TriangleSpec::b).doc("Second vertex."),
              corner("c", &TriangleSpec::c).doc("Third vertex."),
              readByEntry<TriangleSpec>("na", AttrType::Direction)
                  .doc("Vertex normal at a (normalised; give na, nb and nc together). Normals are "
                       "interpolated with the barycentric coordinates and normalised again."),
              readByEntry<TriangleSpec>("nb", AttrType::Direction).doc("Vertex normal at b."),
              readByEntry<TriangleSpec>("nc", AttrType::Direction).doc("Vertex normal at c.")};
  e.finish = [](TriangleSpec& t, AttributeInput& in) {
    bool complete = true;
    for (const char* c : {"a", "b", "c"})
      if (!in.has(c)) {
        in.error(std::string("<triangle> needs the attribute '") + c +
                 "' (its corners a, b and c)");
        complete = false;
      }
    Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
    if (complete && !in.failed() &&
        !(glm::length(glm::cross(e1, e2)) > 1e-12 * glm::length(e1) * glm::length(e2)))
      in.error("<triangle>: the corners a, b and c lie on one line, so the triangle has no area");
    int given = in.has("na") + in.has("nb") + in.has("nc");
    if (given == 3)
      t.normals = std::array<Vec3, 3>{in.direction("na", Vec3(0.0)), in.direction("nb", Vec3(0.0)),
                                      in.direction("nc", Vec3(0.0))};
    else if (given > 0)
      in.error("<triangle>: give all three vertex normals na, nb and nc, or none");
  };
  e.notSolid = [](const TriangleSpec&) { return std::string("a triangle encloses no volume"); };
  e.triangles = [](const TriangleSpec&) { return 1LL; };
  e.samples = [] {
    TriangleSpec flat{Vec3(0, 0, 0), Vec3(1, 0.2, 0), Vec3(0.1, 1, 0.3), std::nullopt};
    TriangleSpec smooth = flat;
    smooth.normals =
        std::array<Vec3, 3>{glm::normalize(Vec3(0.1, 0.2, 1)), glm::normalize(Vec3(-0.2, 0, 1)),
                            glm::normalize(Vec3(0, -0.3, 1))};
    return std::vector<std::pair<std::string, TriangleSpec>>{{"triangle", flat},
                                                             {"smooth triangle", smooth}};
  };
  return e;
}

}  // namespace lucent
