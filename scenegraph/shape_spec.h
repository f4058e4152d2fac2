// The parameters of each geometry element exactly as the scene gave them. The parser fills
// these; the world builder turns them into primitives; the POV-Ray exporter reads them.
#pragma once

#include "primitives/bicubic_patch.h"
#include "primitives/blob_component.h"
#include "primitives/height_map.h"
#include "primitives/isosurface.h"
#include "primitives/julia_map.h"
#include "primitives/lathe_spline.h"
#include "primitives/math.h"
#include "primitives/mesh_data.h"
#include "primitives/parametric.h"
#include "primitives/prism_outline.h"
#include "primitives/sphere_sweep.h"
#include "primitives/text_outline.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace lucent {

struct PigmentFunction;  // pigment_function.h

struct SphereSpec {
  Vec3 center{0.0};
  double radius = 1.0;
};
struct BoxSpec {
  Vec3 min{-1.0};
  Vec3 max{1.0};
};
struct CylinderSpec {
  Vec3 base{0.0};
  Vec3 cap{0.0, 1.0, 0.0};
  double radius = 1.0;
  bool open = false;
};
struct ConeSpec {
  Vec3 base{0.0};
  double baseRadius = 1.0;
  Vec3 cap{0.0, 1.0, 0.0};
  double capRadius = 0.0;
  bool open = false;
};
struct TorusSpec {
  double major = 1.0;
  double minor = 0.25;
};
// The points with normal·x = offset; normal is unit; normal·x < offset is inside.
struct PlaneSpec {
  Vec3 normal{0.0, 1.0, 0.0};
  double offset = 0.0;
};
struct DiscSpec {
  Vec3 center{0.0};
  Vec3 normal{0.0, 1.0, 0.0};  // normal is unit
  double radius = 1.0;
  double innerRadius = 0.0;
};
struct TriangleSpec {
  Vec3 a{0.0}, b{1.0, 0.0, 0.0}, c{0.0, 1.0, 0.0};
  std::optional<std::array<Vec3, 3>> normals;  // unit vertex normals na, nb, nc
};
enum class SmoothMode { Auto, True, False };
// Exponents as POV-Ray's superellipsoid { <e, n> }; the poles lie on the z axis.
struct SuperellipsoidSpec {
  double e = 1.0;
  double n = 1.0;
};
struct MeshSpec {
  std::string src;  // as written ("" for inline meshes)
  SmoothMode smooth = SmoothMode::Auto;
  std::shared_ptr<const MeshData> data;  // loaded, triangulated, oriented
};

// Q(p) = a·(x², y², z²) + b·(xy, xz, yz) + c·(x, y, z) + d; Q < 0 is inside. The default
// is the unit sphere.
struct QuadricSpec {
  Vec3 a{1.0, 1.0, 1.0}, b{0.0}, c{0.0};
  double d = -1.0;
};
// P(x, y, z) < 0 is inside; the coefficients in POV-Ray's order for the order (primitives/poly.h).
struct PolySpec {
  int order = 0;  // required
  std::vector<double> coefficients;
};
// POV-Ray's prism: x z points read by the spline's rules (primitives/prism_outline.h).
struct PrismSpec {
  std::vector<Vec2> points;
  double height1 = 0.0, height2 = 1.0;
  PrismSpline spline = PrismSpline::Linear;
  bool conic = false;  // sweep="conic"
  bool open = false;
};
// POV-Ray's blob: the field of the components above the threshold (primitives/blob.h).
struct BlobSpec {
  double threshold = 1.0;
  std::vector<BlobComponent> components;
  // A material of each component's own (Scene::materials' index), POV-Ray's component
  // texture, weighted at a hit by the component's |field| there; none: the blob's. Empty
  // when no component has one, else one per component.
  std::vector<std::optional<uint32_t>> componentMaterials{};
};
// A curve turned about the y axis, POV-Ray's lathe (primitives/lathe.h).
struct LatheSpec {
  LatheSpline spline = LatheSpline::Linear;
  std::vector<Vec2> points;  // required: x >= 0, y
  bool open = false;         // without the discs that close an open curve (POV-Ray's look)
};
// <isosurface function="..."/>: the function's text and the values of its parameters (for
// the exporter), the compiled field, and the record of the gradients the render saw.
struct IsosurfaceSpec {
  std::string function;  // required
  std::vector<std::pair<std::string, double>> constants;
  std::shared_ptr<const ScalarField> field;
  std::vector<std::shared_ptr<const PigmentFunction>> pigments{};  // the pigments it calls
  double threshold = 0.0;
  IsosurfaceContainer container;
  double maxGradient = 1.1;
  double accuracy = 0.001;
  bool open = false;
  std::shared_ptr<GradientRecord> record = std::make_shared<GradientRecord>();
};
// POV-Ray's text: a string's glyphs in a TrueType or OpenType font (primitives/text_outline.h).
struct TextSpec {
  std::string string;
  std::string font;      // as written ("" for the default font)
  std::string fontPath;  // resolved by the file-access rules ("" for the default font)
  double thickness = 1.0;
  Vec2 offset{0.0};
  std::shared_ptr<const TextOutline> outline;  // laid out when read; null: lay out when built
};
// POV-Ray's surface of revolution: r² a cubic in y per segment (primitives/sor.h).
struct SorSpec {
  std::vector<Vec2> points;  // required: x >= 0, y increasing (the first and last steer)
  bool open = false;
};
// POV-Ray's height_field: the image's grid (primitives/height_field.h), or a function's
// sampled on a grid of `resolution` points (primitives/height_map_function.h).
struct HeightFieldSpec {
  std::string src;   // as written ("" for a function's)
  std::string path;  // resolved, for the POV-Ray file
  // A function's field: its text, parameters and pigment functions as read (as an
  // isosurface's), and the grid's points along x and z.
  std::string function;
  std::vector<std::pair<std::string, double>> constants;
  std::shared_ptr<const ScalarField> field;
  std::vector<std::shared_ptr<const PigmentFunction>> pigments{};
  int resolution[2] = {0, 0};
  bool smooth = false;
  double waterLevel = 0.0;
  bool open = false;                     // without walls and floor (POV-Ray's look)
  std::shared_ptr<const HeightMap> map;  // loaded, or sampled
};
// POV-Ray's polygon: outlines of points in one plane, each closed by repeating its first
// point (primitives/polygon.h); as written (closed when built).
struct PolygonSpec {
  std::vector<Vec3> points;
};
// POV-Ray's bicubic_patch: 16 control points, traced as POV-Ray's triangles
// (primitives/bicubic_patch.h). type: POV-Ray's 0 or 1, the same triangles in both.
// The points and the frame are held by pointer, shared by copies and replaced, never changed
// in place: inline they made every ShapeSpec, and so every Node, 550 bytes.
struct BicubicPatchSpec {
  std::shared_ptr<const PatchPoints> points = std::make_shared<const PatchPoints>();
  int type = 0;
  double flatness = 0.0;
  int uSteps = 0, vSteps = 0;
  PatchUvCorners uvVectors = kPatchOwnUv;  // uv-vectors (POV-Ray's uv_vectors)
  bool flatnessInWorld = false;            // flatness-space="world": measured after every transform
  // Where flatness is measured: the node's world transform when flatnessInWorld, set by the
  // world builder (flatten.cpp) on its copy; null (the identity) as read.
  std::shared_ptr<const Mat4> flatnessFrame;
};
// POV-Ray's julia_fractal: the 3-D slice of a 4-D Julia set (primitives/julia_map.h), its
// parameters as written (the slice made unit when built).
struct JuliaFractalSpec : JuliaParams {};
// POV-Ray's sphere_sweep: control spheres joined by a spline (primitives/sphere_sweep.h).
struct SphereSweepSpec {
  SweepSpline spline = SweepSpline::Linear;
  std::vector<SweepSphere> spheres;  // required: radii >= 0, not all 0
  double tolerance = 1e-6;           // POV-Ray's depth tolerance: written, not used
};
// POV-Ray's ovus: two spheres joined by an arc's surface of revolution (primitives/ovus.h).
struct OvusSpec {
  double bottomRadius = 1.0;  // >= 0, not both 0
  double topRadius = 0.5;
};
// POV-Ray's parametric: three functions of u and v (primitives/parametric.h). Their texts
// and parameters (for the exporter) and compiled fields sit behind a pointer, as does the
// precomputed table (made when the element is read, shared by every copy).
struct ParametricFunctions {
  std::array<std::string, 3> text;
  std::array<std::vector<std::pair<std::string, double>>, 3> constants;
  std::array<std::shared_ptr<const ScalarField>, 3> fields;
};
struct ParametricSpec {
  std::shared_ptr<const ParametricFunctions> functions;  // required
  Vec2 uvMin{0.0}, uvMax{1.0};
  IsosurfaceContainer container;
  double maxGradient = 1.0;
  double accuracy = 0.001;
  int precomputeDepth = 0;
  std::array<bool, 3> precompute{false, false, false};
  std::shared_ptr<const ParametricIntervals> intervals;
};
// The primitive's parameters of a parametric spec.
Parametric::Params parametricParams(const ParametricSpec& s);
// The precomputed table `s` asks for (null for none), shared with every parametric read
// with the same functions, rectangle, max-gradient and precompute while one is alive;
// false, with `problem` set, when the tables alive at once would pass
// kMaxParametricTableBytes.
constexpr size_t kMaxParametricTableBytes = size_t(1) << 30;
bool shareParametricIntervals(ParametricSpec& s, std::string& problem);
using ShapeSpec = std::variant<SphereSpec, BoxSpec, CylinderSpec, ConeSpec, TorusSpec, PlaneSpec,
                               DiscSpec, TriangleSpec, MeshSpec, QuadricSpec, SuperellipsoidSpec,
                               PolySpec, PrismSpec, BlobSpec, LatheSpec, IsosurfaceSpec, TextSpec,
                               SorSpec, HeightFieldSpec, PolygonSpec, BicubicPatchSpec,
                               JuliaFractalSpec, SphereSweepSpec, OvusSpec, ParametricSpec>;
// Every node holds a ShapeSpec inline, so the largest shape sets the size of a sphere's node
// in a scene of a million: a new shape's bulk goes behind a pointer, as the bicubic patch's.
static_assert(sizeof(ShapeSpec) <= 240, "a shape spec this large makes every Node larger");

}  // namespace lucent
