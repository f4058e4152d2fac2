// <bicubic-patch points="16 points" type="0" flatness="0" u-steps="0" v-steps="0"/>:
// POV-Ray 3.7's bicubic_patch, traced as the triangles POV-Ray traces
// (primitives/bicubic_patch.h). Not a solid.
#include "scenegraph/shape_type.h"

#include "primitives/bicubic_patch.h"

#include <fmt/format.h>

namespace lucent {

namespace {

Field<BicubicPatchSpec> whole(const char* name, const char* doc) {
  Field<BicubicPatchSpec> f = readByEntry<BicubicPatchSpec>(name, AttrType::Number, "0");
  f.info.schemaType = "wholeNumber";
  return std::move(f).doc(doc);
}

void readPatch(BicubicPatchSpec& s, AttributeInput& in) {
  const int most = BicubicPatch::kMaxSteps;
  s.type = static_cast<int>(in.integer("type", s.type, 0, 1));
  s.flatnessInWorld = in.choice("flatness-space", 0, {"object", "world"}) == 1;
  s.uSteps = static_cast<int>(in.integer("u-steps", s.uSteps, 0, most));
  s.vSteps = static_cast<int>(in.integer("v-steps", s.vSteps, 0, most));
  if (!in.has("points")) {
    in.error("<bicubic-patch> needs 'points' (its 16 control points, x y z each)");
    return;
  }
  auto list = in.numbers("points");
  if (!list) return;
  if (list->size() != 48) {
    in.attrError("points",
                 fmt::format("expected 16 control points of x y z (48 numbers), got {} numbers",
                             list->size()));
    return;
  }
  PatchPoints points{};
  for (size_t i = 0; i < 16; ++i)
    points[i] = Vec3((*list)[3 * i], (*list)[3 * i + 1], (*list)[3 * i + 2]);
  s.points = std::make_shared<const PatchPoints>(points);
  if (!in.has("uv-vectors")) return;
  auto uv = in.numbers("uv-vectors");
  if (!uv) return;
  if (uv->size() != 8) {
    in.attrError(
        "uv-vectors",
        fmt::format("expected the (u, v) of 4 corners (8 numbers), got {} numbers", uv->size()));
    return;
  }
  for (size_t i = 0; i < 4; ++i) s.uvVectors[i] = Vec2((*uv)[2 * i], (*uv)[2 * i + 1]);
}

void writePatch(const BicubicPatchSpec& s, PovShapeOut& out) {
  out.open("bicubic_patch");
  out.line(fmt::format("type {} flatness {} u_steps {} v_steps {}", s.type, out.number(s.flatness),
                       s.uSteps, s.vSteps));
  if (s.uvVectors != kPatchOwnUv) {  // last: POV-Ray reads no keyword after it
    std::string corners;
    for (const Vec2& c : s.uvVectors)
      corners +=
          fmt::format("{}<{}, {}>", corners.empty() ? "" : ", ", out.number(c.x), out.number(c.y));
    out.line("uv_vectors " + corners);
  }
  const PatchPoints& p = *s.points;
  for (size_t i = 0; i < 16; i += 4)
    out.line(fmt::format("{}, {}, {}, {}{}", out.vector(p[i]), out.vector(p[i + 1]),
                         out.vector(p[i + 2]), out.vector(p[i + 3]), i < 12 ? "," : ""));
}

// Counted as cut in the patch's own space: with flatness-space="world" the world builder
// may cut it finer or coarser where it is placed.
long long patchTriangles(const BicubicPatchSpec& s) {
  return static_cast<long long>(
      bicubicPatchMesh(*s.points, s.flatness, s.uSteps, s.vSteps)->triangles.size());
}

// A saddle over the unit square and POV-Ray's bezier.pov sample, a sheet bent at its
// corners.
std::vector<std::pair<std::string, BicubicPatchSpec>> patchSamples() {
  PatchPoints saddlePoints{}, sheetPoints{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = i / 3.0, z = j / 3.0;
      saddlePoints[static_cast<size_t>(4 * i + j)] = Vec3(x, (x - 0.5) * (z - 0.5), z);
      const bool cornerI = i == 0 || i == 3, cornerJ = j == 0 || j == 3;
      sheetPoints[static_cast<size_t>(4 * i + j)] =
          Vec3(j, i, cornerI && cornerJ ? (j == 0 ? 2.0 : -2.0) : 0.0);
    }
  BicubicPatchSpec saddle;
  saddle.points = std::make_shared<const PatchPoints>(saddlePoints);
  saddle.uSteps = 3;
  saddle.vSteps = 2;
  BicubicPatchSpec sheet;
  sheet.type = 1;
  sheet.flatness = 0.1;
  sheet.uSteps = sheet.vSteps = 4;
  sheet.flatnessInWorld = true;
  sheet.points = std::make_shared<const PatchPoints>(sheetPoints);
  return {{"saddle patch", saddle}, {"bent sheet patch", sheet}};
}

}  // namespace

template <>
ShapeEntry<BicubicPatchSpec> shapeEntry<BicubicPatchSpec>() {
  ShapeEntry<BicubicPatchSpec> e(
      "bicubic-patch", "bicubic patches",
      [](const BicubicPatchSpec& s) {
        return std::make_shared<BicubicPatch>(*s.points, s.flatness, s.uSteps, s.vSteps,
                                              s.flatnessFrame ? *s.flatnessFrame : Mat4(1.0),
                                              s.uvVectors);
      },
      writePatch);
  e.doc =
      "POV-Ray's bicubic_patch: a Bézier patch of 16 control points, traced as POV-Ray's "
      "triangles of its subdivision (not solid).";
  e.fields = {
      readByEntry<BicubicPatchSpec>("points", AttrType::NumberList, "", {}, 3)
          .doc("The 16 control points, x y z each, four rows of four: point 4i + j is P[i][j], "
               "i along the patch's u, j along its v."),
      whole("type", "POV-Ray's patch type, 0 or 1 (both trace the same triangles). Default 0."),
      numberField("flatness", &BicubicPatchSpec::flatness, NumberRule::nonNegative())
          .doc("A part whose control points lie closer than this to the plane of its corners is "
               "not cut further (0: always cut to the steps)."),
      readByEntry<BicubicPatchSpec>("flatness-space", AttrType::Choice, "object",
                                    {"object", "world"})
          .doc("object (flatness measured in the patch's own coordinates) | world (after every "
               "transform, as POV-Ray measures it)."),
      whole("u-steps", "Halvings along u, 0 to 10: at most 2^u-steps parts. Default 0."),
      whole("v-steps", "Halvings along v, 0 to 10: at most 2^v-steps parts. Default 0."),
      readByEntry<BicubicPatchSpec>("uv-vectors", AttrType::NumberList, "0 0 1 0 1 1 0 1", {}, 2)
          .doc("The texture (u, v) of the corners P00, P03, P33 and P30 (POV-Ray's uv_vectors), "
               "u v each; a point's (u, v) blends them bilinearly. Default the patch's own: "
               "0 0 1 0 1 1 0 1.")};
  e.fields[0].info.required = true;
  e.finish = readPatch;
  e.notSolid = [](const BicubicPatchSpec&) {
    return std::string("a bicubic patch encloses no volume");
  };
  e.triangles = patchTriangles;
  e.samples = patchSamples;
  return e;
}

}  // namespace lucent
