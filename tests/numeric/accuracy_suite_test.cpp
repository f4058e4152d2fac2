// The hard-case suite (docs/accuracy.md): every case of accuracy_cases.h must make no
// wrong hit/miss decision, produce nothing non-finite, and stay within its stated error
// bounds away from grazing. LUCENT_PRINT_ACCURACY=1 prints each family's table.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>

#include "accuracy_cases.h"
#include "tests/test_effort.h"

using namespace lucent::accuracy;
using lucent::test::kRandomEffort;

namespace {

void requireWithinBounds(const std::vector<CaseResult>& results) {
  if (std::getenv("LUCENT_PRINT_ACCURACY")) std::printf("%s\n", markdownTable(results).c_str());
  for (const CaseResult& r : results) {
    INFO(r.group << ": " << r.name << " (" << r.rays << " rays, " << r.compared
                 << " crossings compared, max clear t error " << r.relTClear.max()
                 << ", max clear normal error " << r.angleClear.max() << ")\n"
                 << r.firstProblem);
    CHECK(r.rays > 0);
    if (r.decisionsAsserted) CHECK(r.wrong == 0);
    CHECK(r.nonFinite == 0);
    if (r.boundRelT > 0.0) {
      CHECK(r.relTClear.size() > 0);
      CHECK(r.relTClear.max() <= r.boundRelT);
    }
    if (r.boundAngle > 0.0) {
      CHECK(r.angleClear.size() > 0);
      CHECK(r.angleClear.max() <= r.boundAngle);
    }
  }
}

}  // namespace

TEST_CASE("accuracy: random rays at unit scale", "[numeric][accuracy]") {
  requireWithinBounds(baselineCases(kRandomEffort));
}

TEST_CASE("accuracy: grazing and tangent rays, the torus's hole and axis", "[numeric][accuracy]") {
  requireWithinBounds(grazingCases(kRandomEffort));
}

TEST_CASE("accuracy: unit objects 1e5 from the origin, scenes scaled by 1e-4 and 1e4",
          "[numeric][accuracy]") {
  requireWithinBounds(farAndScaledCases(kRandomEffort));
}

TEST_CASE("accuracy: secondary rays never re-hit the surface they leave", "[numeric][accuracy]") {
  requireWithinBounds(secondaryRayCases(kRandomEffort));
}

TEST_CASE("accuracy: rays with zero direction components", "[numeric][accuracy]") {
  requireWithinBounds(zeroDirectionCases(kRandomEffort));
}

TEST_CASE("accuracy: near-singular transforms through Instance", "[numeric][accuracy]") {
  requireWithinBounds(nearSingularCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: superellipsoids: a near cube grazed at its edges and along its faces, tangent and "
    "secondary rays",
    "[numeric][accuracy][superellipsoid]") {
  requireWithinBounds(superellipsoidCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: quadrics and polys: a cylinder, a cone and a plane as quadrics, a torus as a "
    "quartic, the tangle cube",
    "[numeric][accuracy][quadric][poly]") {
  requireWithinBounds(quadricCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: blobs: tangent rays, a strength just above the threshold, fields just merging, a "
    "carved hole, secondary rays",
    "[numeric][accuracy][blob]") {
  requireWithinBounds(blobCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: isosurfaces: sphere and torus functions, thin shells, a too low max-gradient, "
    "secondary rays",
    "[numeric][accuracy][isosurface]") {
  requireWithinBounds(isosurfaceCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: prisms: a star with a hole, rays through vertices, along side faces, grazing the "
    "caps",
    "[numeric][accuracy][prism]") {
  requireWithinBounds(prismCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: lathes: a Bezier vase and a linear goblet, tangent to the silhouette, through the "
    "axis, at the rims",
    "[numeric][accuracy][lathe]") {
  requireWithinBounds(latheCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: text: o, 8 and e with holes, rays into the holes, along a glyph's edge, through "
    "segment joins",
    "[numeric][accuracy][text]") {
  requireWithinBounds(textCases(kRandomEffort));
}

TEST_CASE(
    "accuracy: sors: tangent to the silhouette, along the axis, through the caps' rims, through "
    "the poles",
    "[numeric][accuracy][sor]") {
  requireWithinBounds(sorCases(kRandomEffort));
}

TEST_CASE("accuracy: sphere sweeps: linear, cubic and b-spline, random and tangent rays",
          "[numeric][accuracy][sweep]") {
  requireWithinBounds(sweepCases(kRandomEffort));
}

TEST_CASE("accuracy: ovuses: both of POV-Ray's forms, random and tangent rays, the seams",
          "[numeric][accuracy][ovus]") {
  requireWithinBounds(ovusCases(1.0));
}

TEST_CASE(
    "accuracy: height fields: random rays, edge-on along grid lines and diagonals, along grid "
    "edges",
    "[numeric][accuracy][height-field]") {
  requireWithinBounds(heightFieldCases(kRandomEffort));
}

TEST_CASE("accuracy: meshes: 10^6 rays from inside all hit, shared edges and vertices, slivers",
          "[numeric][accuracy][mesh]") {
  requireWithinBounds(meshCases(kRandomEffort));
}

// Rays lying exactly along a mesh edge meet the triangles beside it almost edge-on; the
// crossings must still alternate and leave the ray outside (docs/accuracy.md).
TEST_CASE("accuracy: rays along mesh edges keep the crossings' parity",
          "[numeric][accuracy][mesh]") {
  requireWithinBounds(meshAlongEdgeCases(kRandomEffort));
}
