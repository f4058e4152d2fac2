#include "test_meshes.h"

#include "scenegraph/shape_registry.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;

TEST_CASE("makeShape: every element builds its primitive with the spec's parameters",
          "[primitives][scenegraph]") {
  auto mesh = std::make_shared<MeshData>(*boxMesh(Vec3(-1.0), Vec3(1.0)));
  MeshSpec meshSpec;
  meshSpec.data = mesh;
  struct UnitBall final : ScalarField {
    double value(const Vec3& p) const override { return glm::length(p) - 1.0; }
  };
  IsosurfaceSpec iso;
  iso.function = "sqrt(x*x + y*y + z*z) - 1";
  iso.field = std::make_shared<UnitBall>();
  iso.container.min = Vec3(-2.0);
  iso.container.max = Vec3(2.0);
  TriangleSpec tri;
  tri.a = Vec3(-1, -1, 0);
  tri.b = Vec3(1, -1, 0);
  tri.c = Vec3(0, 1, 0);
  const ShapeSpec specs[] = {
      SphereSpec{Vec3(0, 0, 0), 1.0},
      BoxSpec{Vec3(-1.0), Vec3(1.0)},
      CylinderSpec{Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0, false},
      CylinderSpec{Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0, true},
      ConeSpec{Vec3(0, 0, -1), 1.0, Vec3(0, 0, 1), 0.0, false},
      TorusSpec{1.0, 0.25},
      PlaneSpec{Vec3(0, 0, 1), 1.0},
      DiscSpec{Vec3(0.0), Vec3(0, 0, 1), 1.0, 0.0},
      tri,
      meshSpec,
      SuperellipsoidSpec{0.3, 0.7},
      PrismSpec{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}, -1.0, 1.0},
      iso,
  };
  // Every one of them is crossed by the z axis from z = 5 first at z = 1 (the torus at its
  // tube: the ray runs at x = 1 for it; the open cylinder from the side) or, for the flat
  // ones, at z = 0.
  auto isOpenCylinder = [](const ShapeSpec& s) {
    return std::holds_alternative<CylinderSpec>(s) && std::get<CylinderSpec>(s).open;
  };
  for (const ShapeSpec& spec : specs) {
    std::shared_ptr<const Shape> s = makeShape(spec);
    INFO(shapeElementName(spec));
    CHECK(std::string(s->kind()) == shapeElementName(spec));
    CHECK(s->isSolid() == isSolid(spec));
    bool torus = std::holds_alternative<TorusSpec>(spec);
    bool open = isOpenCylinder(spec);
    Ray ray = torus  ? Ray(Vec3(1, 5, 0), Vec3(0, -1, 0))
              : open ? Ray(Vec3(5, 0, 0), Vec3(-1, 0, 0))  // no caps: through the side
                     : Ray(Vec3(0, 0, 5), Vec3(0, 0, -1));
    Hit h;
    REQUIRE(s->intersect(ray, h));
    bool flat =
        std::holds_alternative<DiscSpec>(spec) || std::holds_alternative<TriangleSpec>(spec);
    CHECK_THAT(h.t, WithinAbs(torus ? 4.75 : flat ? 5.0 : 4.0, 1e-14));
  }
}

TEST_CASE("makeShape: the mesh's smooth modes", "[primitives][scenegraph]") {
  auto octa = octahedronMesh();  // has normals along the axes
  MeshSpec spec;
  spec.data = octa;
  Vec3 target(0.5, 0.25, 0.25);  // on the face (+x, +y, +z), barycentrics (0.5, 0.25, 0.25)
  Ray ray(target + Vec3(1.0), -Vec3(1.0));
  auto shadingNormal = [&](SmoothMode mode) {
    spec.smooth = mode;
    auto s = makeShape(spec);
    Hit h;
    REQUIRE(s->intersect(ray, h));
    return s->surface(ray, h).ns;
  };
  Vec3 flat = glm::normalize(Vec3(1.0));
  Vec3 fromFile = glm::normalize(Vec3(0.5, 0.25, 0.25));
  // Computed: each corner's normal averages its four faces (equal areas): along the axis,
  // so here the same as the file's.
  Vec3 autoN = shadingNormal(SmoothMode::Auto);
  CHECK_THAT(glm::dot(autoN, fromFile), WithinAbs(1.0, 1e-14));
  Vec3 falseN = shadingNormal(SmoothMode::False);
  CHECK_THAT(glm::dot(falseN, flat), WithinAbs(1.0, 1e-14));
  Vec3 trueN = shadingNormal(SmoothMode::True);
  CHECK_THAT(glm::dot(trueN, fromFile), WithinAbs(1.0, 1e-14));

  // Without file normals, auto is flat; true differs from the file-less flat one.
  auto bare = std::make_shared<MeshData>(*octa);
  bare->normals.clear();
  spec.data = bare;
  CHECK_THAT(glm::dot(shadingNormal(SmoothMode::Auto), flat), WithinAbs(1.0, 1e-14));
  CHECK_THAT(glm::dot(shadingNormal(SmoothMode::True), fromFile), WithinAbs(1.0, 1e-14));
  CHECK(bare->normals.empty());  // the spec's data is never modified
}

TEST_CASE("makeShape: impossible parameters throw std::invalid_argument",
          "[primitives][scenegraph]") {
  const ShapeSpec bad[] = {
      SphereSpec{Vec3(0.0), 0.0},
      SphereSpec{Vec3(0.0), -1.0},
      CylinderSpec{Vec3(1.0), Vec3(1.0), 1.0, false},
      CylinderSpec{Vec3(0.0), Vec3(0, 1, 0), 0.0, false},
      ConeSpec{Vec3(0.0), 0.0, Vec3(0, 1, 0), 0.0, false},
      ConeSpec{Vec3(0.0), -1.0, Vec3(0, 1, 0), 0.0, false},
      ConeSpec{Vec3(0.0), 1.0, Vec3(0.0), 0.5, false},
      TorusSpec{1.0, 0.0},
      TorusSpec{-1.0, 0.25},
      PlaneSpec{Vec3(0.0), 1.0},
      DiscSpec{Vec3(0.0), Vec3(0, 1, 0), 1.0, 1.0},
      DiscSpec{Vec3(0.0), Vec3(0, 1, 0), 0.0, 0.0},
      DiscSpec{Vec3(0.0), Vec3(0.0), 1.0, 0.0},
      SuperellipsoidSpec{0.0, 1.0},
      SuperellipsoidSpec{1.0, 20.0},
  };
  for (const ShapeSpec& spec : bad) {
    INFO(shapeElementName(spec));
    CHECK_THROWS_AS(makeShape(spec), std::invalid_argument);
  }
  auto broken = std::make_shared<MeshData>(*squareMesh());
  broken->triangles.push_back({0, 1, 7});
  MeshSpec m;
  m.data = broken;
  CHECK_THROWS_WITH(makeShape(m), "mesh: triangle 2 uses vertex 7, but there are only 4");
}
