// The shapes: each POV-Ray 3.7 shape's parameters read as POV-Ray reads them (its parser,
// source/parser/parser.cpp, taken as facts), carried into Lucent's space (z negated:
// pov_space.h); what Lucent cannot take within a shape is refused where it is written.
// docs/povray-import.md ("The scene reader") lists each shape's mapping.
#include "read_support.h"
#include "scene_reader.h"

#include "images/height_map_file.h"
#include "meshes/mesh_repair.h"
#include "primitives/blob.h"
#include "primitives/height_map_function.h"
#include "primitives/lathe.h"
#include "primitives/poly.h"
#include "primitives/polygon.h"
#include "primitives/sor.h"
#include "primitives/sphere_sweep.h"
#include "primitives/superellipsoid.h"
#include "scenegraph/pigment_function.h"
#include "scenegraph/shape_type.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace lucent::sdl {

namespace {

// POV-Ray's EPSILON, its tolerance for degenerate input.
constexpr double kPovEpsilon = 1e-10;

constexpr std::string_view kShapes[] = {"sphere",         "box",           "plane",
                                        "cylinder",       "cone",          "torus",
                                        "disc",           "triangle",      "smooth_triangle",
                                        "quadric",        "poly",          "cubic",
                                        "quartic",        "polynomial",    "blob",
                                        "lathe",          "sor",           "prism",
                                        "superellipsoid", "text",          "height_field",
                                        "mesh",           "mesh2",         "isosurface",
                                        "polygon",        "bicubic_patch", "julia_fractal",
                                        "sphere_sweep",   "ovus",          "parametric"};

Vec3 point(TokenStream& in) { return lucentFromPov(toVec3(in.parseVector())); }

// A direction made unit, or an error at `at` when it has no length.
Vec3 unitDirection(TokenStream& in, const Token& at, const Vec3& v, const char* what) {
  const double len = glm::length(v);
  if (!(len > 0.0)) in.error(at, std::string("the ") + what + " has no length");
  return v / len;
}

// POV-Ray's 2-D vector (Parse_UV_Vect): `<u, v>`, or a float f as <f, f>.

// A count POV-Ray reads as a float and truncates (`(int)Parse_Float()`), bounded so that a
// wild number is an error, not an allocation.
int parseCount(TokenStream& in, const char* what, int most = 1 << 24) {
  const Token& at = in.peek();
  const SourceLoc loc = at.loc();
  const double f = in.parseFloat();
  if (!(f >= 0.0) || f > most)
    in.error(loc, std::string("the ") + what + " must be from 0 to " + std::to_string(most));
  return static_cast<int>(f);
}

// Reads a flag keyword that follows the shape's parameters (POV-Ray's AllowToken).
bool allowWord(TokenStream& in, std::string_view word) {
  if (!isWord(in.peek(), word)) return false;
  in.next();
  return true;
}

// The powers (i, j, k) of x, y, z of each of poly's coefficients of `order`, in POV-Ray's
// order: i descending, then j, then k.
std::vector<std::array<int, 3>> polyTerms(int order) {
  std::vector<std::array<int, 3>> terms;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) terms.push_back({i, j, k});
  return terms;
}

// z → −z changes the sign of each term with an odd power of z.
void mirrorPoly(PolySpec& s) {
  const auto terms = polyTerms(s.order);
  for (size_t n = 0; n < terms.size(); ++n)
    if (terms[n][2] % 2 != 0) s.coefficients[n] = -s.coefficients[n];
}

// Whether the linear part of `m` is a rotation or mirror times a uniform scale; its scale.
bool similarity(const Mat4& m, double& scale) {
  const Vec3 c[3] = {Vec3(m[0]), Vec3(m[1]), Vec3(m[2])};
  scale = glm::length(c[0]);
  const double tol = 1e-9 * std::max(1.0, scale * scale);
  for (int i = 0; i < 3; ++i) {
    if (std::abs(glm::dot(c[i], c[i]) - scale * scale) > tol) return false;
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(glm::dot(c[i], c[j])) > tol) return false;
  }
  return scale > 0.0;
}

// POV-Ray's 4-D vector: a float is all four components, a shorter vector padded with 0.
Vec4 parseVector4(TokenStream& in) {
  const SourceLoc loc = in.peek().loc();
  const Value v = in.parseExpression();
  const int n = v.terms();
  if (n < 1 || n > 4) in.error(loc, "expected a 4-D vector, not a " + typeName(v));
  if (n == 1) return Vec4(v.v[0]);
  Vec4 out(0.0);
  for (int i = 0; i < n; ++i) out[i] = v.v[static_cast<size_t>(i)];
  return out;
}

}  // namespace

Vec2 parseUv(TokenStream& in) {
  const SourceLoc at = in.peek().loc();
  const Value v = in.parseExpression();
  if (v.terms() == 1) return Vec2(v.v[0]);
  if (v.terms() != 2)
    in.error(at, "a 2-D vector <u, v> expected, not one of " + std::to_string(v.terms()) +
                     " components");
  return Vec2(v.v[0], v.v[1]);
}

bool isShapeKeyword(std::string_view word) {
  return std::find(std::begin(kShapes), std::end(kShapes), word) != std::end(kShapes);
}

// What Lucent cannot render in a shape: an error at `at` kept now, or, while a #declare is
// read, kept with the declared item and said where the item is used (a library such as
// shapesq.inc declares shapes a scene may never use): SceneReader::refusal.
void SceneReader::refuse(PovObject& o, const SourceLoc& at, TokenStream& in,
                         const std::string& message) {
  (void)o;
  refusal(in, at, message, true);
}

// refuse(), then the rest of the shape's block skipped, its closing brace left to be read:
// the object has no shape (the scene is not made), and reading goes on, so that every such
// place is listed.
void SceneReader::refuseShape(PovObject& o, const SourceLoc& at, TokenStream& in,
                              const std::string& message) {
  refuse(o, at, in, message);
  int depth = 1;
  for (;;) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) in.error(t, "the block is not closed ('}' expected)");
    if (t.is("{")) ++depth;
    if (t.is("}") && --depth == 0) break;
  }
  in.unget();
}

// The shape's own parameters, as POV-Ray writes them, into Lucent's space.
void SceneReader::readShape(PovObject& o, TokenStream& in) {
  const Token at = in.current();
  const std::string& w = o.keyword;
  if (w == "sphere") {
    SphereSpec s;
    s.center = point(in);
    in.parseComma();
    s.radius = in.parseFloat();
    o.shape = s;
  } else if (w == "box") {
    const Vec3 a = point(in);
    in.parseComma();
    const Vec3 b = point(in);
    o.shape = BoxSpec{glm::min(a, b), glm::max(a, b)};
  } else if (w == "plane") {
    // POV-Ray makes the normal unit and keeps the distance: `plane { <0, 2, 0>, 1 }` is at
    // y = 1 (its Parse_Plane; its images say so).
    const Vec3 n = toVec3(in.parseVector());
    in.parseComma();
    const double d = in.parseFloat();
    const double len = glm::length(n);
    if (!(len > 0.0)) in.error(at, "the plane's normal has no length");
    o.shape = PlaneSpec{lucentFromPov(n / len), d};
  } else if (w == "cylinder") {
    CylinderSpec s;
    s.base = point(in);
    in.parseComma();
    s.cap = point(in);
    in.parseComma();
    s.radius = in.parseFloat();
    o.shape = s;
  } else if (w == "cone") {
    ConeSpec s;
    s.base = point(in);
    in.parseComma();
    s.baseRadius = in.parseFloat();
    in.parseComma();
    s.cap = point(in);
    in.parseComma();
    s.capRadius = in.parseFloat();
    o.shape = s;
  } else if (w == "torus") {
    TorusSpec s;
    s.major = in.parseFloat();
    in.parseComma();
    s.minor = in.parseFloat();
    o.shape = s;  // in the xz-plane about y: the same in both spaces
  } else if (w == "ovus") {
    readOvus(o, in);
  } else if (w == "parametric") {
    readParametric(o, in);
  } else if (w == "disc") {
    DiscSpec s;
    s.center = point(in);
    in.parseComma();
    s.normal = unitDirection(in, at, point(in), "disc's normal");
    in.parseComma();
    s.radius = in.parseFloat();
    if (in.allow(",")) s.innerRadius = in.parseFloat();
    o.shape = s;
  } else if (w == "triangle") {
    TriangleSpec s;
    s.a = point(in);
    in.parseComma();
    s.b = point(in);
    in.parseComma();
    s.c = point(in);
    o.shape = s;
  } else if (w == "smooth_triangle") {
    // POV-Ray makes the normals unit; a zero one makes the triangle degenerate (not drawn).
    TriangleSpec s;
    std::array<Vec3, 3> n{};
    Vec3* corner[3] = {&s.a, &s.b, &s.c};
    for (size_t k = 0; k < 3; ++k) {
      if (k > 0) in.parseComma();
      *corner[k] = point(in);
      in.parseComma();
      const SourceLoc normalAt = in.peek().loc();
      n[k] = point(in);
      const double len = glm::length(n[k]);
      if (!(len > 0.0)) in.error(normalAt, "the smooth_triangle's normal has no length");
      n[k] /= len;
    }
    s.normals = n;
    o.shape = s;
  } else if (w == "isosurface") {
    readIsosurface(o, in);
  } else if (w == "quadric") {
    readQuadric(o, in);
  } else if (w == "poly" || w == "cubic" || w == "quartic" || w == "polynomial") {
    readPoly(o, in);
  } else if (w == "blob") {
    readBlob(o, in);
  } else if (w == "lathe" || w == "sor") {
    readLatheOrSor(o, in);
  } else if (w == "prism") {
    readPrism(o, in);
  } else if (w == "polygon") {
    readPolygon(o, in);
  } else if (w == "bicubic_patch") {
    readBicubicPatch(o, in);
  } else if (w == "julia_fractal") {
    readJuliaFractal(o, in);
  } else if (w == "sphere_sweep") {
    readSphereSweep(o, in);
  } else if (w == "superellipsoid") {
    Vec2 en = parseUv(in);
    // Below 0.01 the shape is a box to within 0.35 % of its half-width at the corners
    // (1 − 2^−(e/2)): drawn with 0.01, said in a warning. POV-Ray takes any exponent > 0.
    const double least = Superellipsoid::kMinExponent;
    if ((en.x > 0.0 && en.x < least) || (en.y > 0.0 && en.y < least)) {
      warn(in, o.loc,
           "'superellipsoid' exponents below 0.01 are drawn as 0.01, the least Lucent takes "
           "(here <" +
               attributeText(en.x) + ", " + attributeText(en.y) +
               ">): the shape's corners and edges move by at most 0.35 % of its half-width");
      en = glm::max(en, Vec2(least));
    }
    // Poles on z in both: z → −z maps the shape onto itself.
    if (!(en.x >= Superellipsoid::kMinExponent && en.x <= Superellipsoid::kMaxExponent &&
          en.y >= Superellipsoid::kMinExponent && en.y <= Superellipsoid::kMaxExponent))
      refuseShape(o, o.loc, in,
                  "'superellipsoid' exponents of 0 or less, or above 10, are not supported by "
                  "Lucent (here "
                  "<" +
                      attributeText(en.x) + ", " + attributeText(en.y) +
                      ">; Lucent's root isolation is tested from nearly a box to a sharp star)");
    else o.shape = SuperellipsoidSpec{en.x, en.y};
  } else if (w == "text") {
    readText(o, in);
  } else if (w == "height_field") {
    readHeightField(o, in);
  } else if (w == "mesh") {
    readMesh(o, in);
  } else if (w == "mesh2") {
    readMesh2(o, in);
  }
}

// ovus { bottom_radius, top_radius }: about the y axis, the same in both spaces. POV-Ray's
// error for a negative radius; both 0, where POV-Ray makes a sphere of radius 0 (nothing
// drawn), is an error; a top radius of twice the bottom one or more, which POV-Ray turns
// into its top sphere with a warning, is that sphere in Lucent too.
void SceneReader::readOvus(PovObject& o, TokenStream& in) {
  OvusSpec s;
  const SourceLoc at = in.peek().loc();
  s.bottomRadius = in.parseFloat();
  in.parseComma();
  s.topRadius = in.parseFloat();
  if (!(s.bottomRadius >= 0.0 && s.topRadius >= 0.0))
    in.error(at, "both of the ovus's radii must be >= 0");
  if (s.bottomRadius == 0.0 && s.topRadius == 0.0)
    in.error(at, "the ovus's radii are both 0: it has no surface");
  o.shape = s;
}

// quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }: A x² + B y² + C z² + D xy + E xz + F yz
// + G x + H y + I z + J. Under z → −z the terms odd in z (xz, yz, z) change sign.
void SceneReader::readQuadric(PovObject& o, TokenStream& in) {
  const Vec3 a = toVec3(in.parseVector());
  in.parseComma();
  const Vec3 b = toVec3(in.parseVector());
  in.parseComma();
  const Vec3 c = toVec3(in.parseVector());
  in.parseComma();
  const double d = in.parseFloat();
  QuadricSpec q{a, Vec3(b.x, -b.y, -b.z), Vec3(c.x, c.y, -c.z), d};
  if (q.a == Vec3(0.0) && q.b == Vec3(0.0) && q.c == Vec3(0.0))
    in.error(o.loc, "the quadric's coefficients are all 0 but the constant: it has no surface");
  o.shape = q;
}

// poly { ORDER, <c...> }, cubic { <20 c> }, quartic { <35 c> }, and POV-Ray 3.7's
// polynomial { ORDER, xyz(i, j, k): c ... }: orders 2 to 35, as POV-Ray (its MAX_ORDER).
void SceneReader::readPoly(PovObject& o, TokenStream& in) {
  const std::string& w = o.keyword;
  int order = w == "cubic" ? 3 : w == "quartic" ? 4 : 0;
  if (order == 0) {
    const SourceLoc loc = in.peek().loc();
    const double f = in.parseFloat();
    in.parseComma();
    if (!(f >= 2.0 && f < 36.0)) in.error(loc, "the order of a " + w + " must be from 2 to 35");
    order = static_cast<int>(f);
  }
  PolySpec s;
  s.order = order;
  const auto terms = polyTerms(order);
  s.coefficients.assign(terms.size(), 0.0);
  if (w == "polynomial") {
    while (isWord(in.peek(), "xyz")) {
      const Token xyz = in.next();
      in.expect("(");
      std::array<int, 3> p{};
      for (int i = 0; i < 3; ++i) {
        if (i > 0) in.parseComma();
        p[static_cast<size_t>(i)] = static_cast<int>(in.parseFloat());
      }
      in.expect(")");
      in.expect(":");
      const double value = in.parseFloat();
      in.parseComma();
      const auto it = std::find(terms.begin(), terms.end(), p);
      if (it == terms.end())
        in.error(xyz, "xyz(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                          std::to_string(p[2]) + ") is not a term of a polynomial of order " +
                          std::to_string(order));
      s.coefficients[static_cast<size_t>(it - terms.begin())] = value;
    }
  } else {
    in.expect("<");
    for (size_t i = 0; i < terms.size(); ++i) {
      if (i > 0) in.parseComma();
      s.coefficients[i] = in.parseFloat();
    }
    in.expect(">");
  }
  bool surface = false;
  for (size_t i = 0; i + 1 < s.coefficients.size(); ++i) surface |= s.coefficients[i] != 0.0;
  if (!surface)
    in.error(o.loc, "every coefficient of the " + w + " but the constant is 0: it has no surface");
  mirrorPoly(s);
  o.shape = std::move(s);
}

// blob { threshold T  sphere { C, R, [strength] S }  cylinder { B, A, R, [strength] S }
// component S, R, C }: the components in any order, then the blob's modifiers. A
// component's translate, rotate, uniform scale and matrix are carried into its centre, ends
// and radius (the field moves with them exactly); any other transform (an ellipsoid, a
// sheared cylinder) becomes the component's own transform. A component's own texture
// Lucent's blob cannot hold.
void SceneReader::readBlob(PovObject& o, TokenStream& in) {
  BlobSpec s;
  s.threshold = 1.0;
  o.componentTextures.clear();
  o.componentTextureLocs.clear();
  for (;;) {
    const Token t = in.next();
    if (isWord(t, "threshold")) {
      s.threshold = in.parseFloat();
    } else if (isWord(t, "component")) {
      BlobComponent c;
      c.strength = in.parseFloat();
      in.parseComma();
      c.radius = std::abs(in.parseFloat());  // POV-Ray keeps its square
      in.parseComma();
      c.a = toVec3(in.parseVector());
      if (!(c.radius > 0.0)) in.error(t, "the blob component's radius is 0");
      c.a = lucentFromPov(c.a);
      s.components.push_back(c);
      if (!o.componentTextures.empty()) {
        o.componentTextures.emplace_back();
        o.componentTextureLocs.emplace_back();
      }
    } else if (isWord(t, "sphere") || isWord(t, "cylinder")) {
      BlobComponent c;
      c.kind = isWord(t, "sphere") ? BlobComponent::Sphere : BlobComponent::Cylinder;
      in.expect("{");
      c.a = toVec3(in.parseVector());
      in.parseComma();
      if (c.kind == BlobComponent::Cylinder) {
        c.b = toVec3(in.parseVector());
        in.parseComma();
      }
      c.radius = std::abs(in.parseFloat());
      in.parseComma();
      allowWord(in, "strength");
      c.strength = in.parseFloat();
      if (!(c.radius > 0.0)) in.error(t, "the blob component's radius is 0");
      if (c.kind == BlobComponent::Cylinder && glm::length(c.b - c.a) < kPovEpsilon)
        in.error(t, "the blob's cylinder component has no length (its ends are the same point)");
      // The component's transforms and texture, read as an object's (a texture follows
      // only the transforms written after it).
      PovObject part;
      part.keyword = "blob component";
      PovTransform& m = part.transform;
      for (;;) {
        const Token mod = in.next();
        if (mod.is("}")) break;
        if (readTransform(mod, in, m)) continue;
        if (isWord(mod, "texture") || isWord(mod, "pigment") || isWord(mod, "finish") ||
            isWord(mod, "normal")) {
          readObjectModifier(mod, part, in);
          continue;
        }
        in.error(mod, "unexpected " + mod.describe() + " in a blob component");
      }
      if (part.texture) {
        PovTexture own = *part.texture;
        own.transform(m);  // into the blob's space
        o.componentTextures.resize(s.components.size());
        o.componentTextureLocs.resize(s.components.size());
        o.componentTextures.push_back(std::move(own));
        o.componentTextureLocs.push_back(part.textureLoc);
      } else if (!o.componentTextures.empty()) {
        o.componentTextures.emplace_back();
        o.componentTextureLocs.emplace_back();
      }
      double scale = 1.0;
      if (similarity(m.povMatrix(), scale)) {
        c.a = lucentFromPov(m.point(c.a));
        c.b = lucentFromPov(m.point(c.b));
        c.radius *= scale;
      } else {
        if (!(std::abs(glm::determinant(Mat3(m.povMatrix()))) > 0.0))
          in.error(t, "the blob component's transform is singular (a scale of 0)");
        c.a = lucentFromPov(c.a);
        c.b = lucentFromPov(c.b);
        c.transform = m.lucentMatrix();
      }
      s.components.push_back(c);
    } else {
      in.unget();
      break;
    }
  }
  if (s.components.empty()) in.error(o.loc, "the blob has no component");
  if (!(s.threshold > 0.0))
    refuseShape(o, o.loc, in,
                "a blob threshold of " + attributeText(s.threshold) +
                    " is not supported by Lucent (it takes a threshold above 0: at or below 0 all "
                    "of space away from the components would be inside)");
  else o.shape = std::move(s);
}

// lathe { [SPLINE] N, <x, y>... } and sor { N, <x, y>... [open] }: curves turned about the
// y axis, the same in both spaces. Lucent's own rules (every point's x >= 0, a lathe of
// some extent, a sor's slopes defined) are said at the shape, after POV-Ray's.
void SceneReader::readLatheOrSor(PovObject& o, TokenStream& in) {
  const bool lathe = o.keyword == "lathe";
  LatheSpline spline = LatheSpline::Linear;
  while (lathe) {
    if (allowWord(in, "linear_spline")) spline = LatheSpline::Linear;
    else if (allowWord(in, "quadratic_spline")) spline = LatheSpline::Quadratic;
    else if (allowWord(in, "cubic_spline")) spline = LatheSpline::Cubic;
    else if (allowWord(in, "bezier_spline")) spline = LatheSpline::Bezier;
    else break;
  }
  const SourceLoc countLoc = in.peek().loc();
  const int n = parseCount(in, "number of points");
  if (lathe) {
    const char* rule = spline == LatheSpline::Linear ? "a linear lathe needs 2 points or more"
                       : spline == LatheSpline::Quadratic
                           ? "a quadratic lathe needs 3 points or more"
                       : spline == LatheSpline::Cubic ? "a cubic lathe needs 4 points or more"
                                                      : "a bezier lathe needs 4 points a segment";
    if (n < Lathe::minPoints(spline) || (spline == LatheSpline::Bezier && n % 4 != 0))
      in.error(countLoc, std::string(rule) + ", not " + std::to_string(n));
  } else if (n < 4) {
    in.error(countLoc, "a sor needs 4 points or more, not " + std::to_string(n));
  }
  in.parseComma();
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) {
    points.push_back(parseUv(in));
    in.parseComma();  // POV-Ray allows a trailing comma
  }
  if (lathe) {
    try {
      Lathe check(spline, points);
    } catch (const std::invalid_argument& e) {
      refuseShape(o, o.loc, in,
                  std::string("this lathe is not supported by Lucent (") + e.what() +
                      "; POV-Ray allows x < 0 at some control points)");
      return;
    }
    // Where the curve starts and ends: Lucent closes an open curve by discs to the axis
    // unless the lathe is open, as POV-Ray's is (closed again within a CSG: closeForCsg).
    const size_t last = points.size() - 1;
    const Vec2 first =
        points[spline == LatheSpline::Quadratic || spline == LatheSpline::Cubic ? 1 : 0];
    const Vec2 end = points[spline == LatheSpline::Cubic ? last - 1 : last];
    const bool open = first != end && (first.x != 0.0 || end.x != 0.0);
    o.shape = LatheSpec{spline, points, open};
    return;
  }
  for (int i = 0; i < n; ++i)
    if (points[static_cast<size_t>(i)].x < 0.0 ||
        (i > 1 && i < n - 1 &&
         points[static_cast<size_t>(i)].y <= points[static_cast<size_t>(i - 1)].y))
      in.error(o.loc, "point " + std::to_string(i + 1) +
                          " of the sor is incorrect (x < 0, or not above the point before)");
  const bool open = allowWord(in, "open");
  try {
    Sor check(points, open);
  } catch (const std::invalid_argument& e) {
    refuseShape(o, o.loc, in,
                std::string("this sor is not supported by Lucent (") + e.what() + ")");
    return;
  }
  o.shape = SorSpec{points, open};
}

// prism { [linear_sweep|conic_sweep] [SPLINE] H1, H2, N, <x, z>... [open] }: the points are
// x z in POV-Ray's space, (x, −z) in Lucent's.
void SceneReader::readPrism(PovObject& o, TokenStream& in) {
  PrismSpec s;
  for (;;) {
    if (allowWord(in, "linear_spline")) s.spline = PrismSpline::Linear;
    else if (allowWord(in, "quadratic_spline")) s.spline = PrismSpline::Quadratic;
    else if (allowWord(in, "cubic_spline")) s.spline = PrismSpline::Cubic;
    else if (allowWord(in, "bezier_spline")) s.spline = PrismSpline::Bezier;
    else if (allowWord(in, "linear_sweep")) s.conic = false;
    else if (allowWord(in, "conic_sweep")) s.conic = true;
    else break;
  }
  s.height1 = in.parseFloat();
  in.parseComma();
  s.height2 = in.parseFloat();
  in.parseComma();
  if (s.height1 > s.height2) std::swap(s.height1, s.height2);
  const SourceLoc countLoc = in.peek().loc();
  const int n = parseCount(in, "number of points");
  const int least = s.spline == PrismSpline::Linear      ? 3
                    : s.spline == PrismSpline::Quadratic ? 5
                    : s.spline == PrismSpline::Cubic     ? 6
                                                         : 4;
  if (n < least || (s.spline == PrismSpline::Bezier && n % 4 != 0))
    in.error(countLoc, s.spline == PrismSpline::Bezier
                           ? "a bezier prism needs 4 points a segment, not " + std::to_string(n)
                           : "this prism needs " + std::to_string(least) + " points or more, not " +
                                 std::to_string(n));
  in.parseComma();
  for (int i = 0; i < n; ++i) {
    const Vec2 p = parseUv(in);
    s.points.emplace_back(p.x, -p.y);
    in.parseComma();
  }
  s.open = allowWord(in, "open");
  const PrismOutline outline = prismOutline(s.points, s.spline);
  if (!outline.error.empty()) in.error(o.loc, "the prism's points: " + outline.error);
  if (outline.closedLast)
    warn(in, o.loc,
         "the prism's last polygon is not closed (its first point is not repeated); "
         "closed it, as POV-Ray does");
  if (s.height1 == s.height2) in.error(o.loc, "the prism's two heights are equal: it is flat");
  o.shape = std::move(s);
}

// polygon { N, <x, y, z>... }: 2-D points have z = 0 (POV-Ray's vectors). POV-Ray closes an
// unclosed last outline with a warning, and ignores a polygon whose points lie on one line
// or not in one plane (within 1e-10): Lucent leaves it out, with a warning.
void SceneReader::readPolygon(PovObject& o, TokenStream& in) {
  const SourceLoc countLoc = in.peek().loc();
  const double n = in.parseFloat();
  if (!(n >= 3.0))
    in.error(countLoc, "a polygon needs at least three points, not " + attributeText(n));
  if (n > (1 << 24)) in.error(countLoc, "a polygon of more than 16777216 points");
  in.parseComma();
  PolygonSpec s;
  for (int i = 0; i < static_cast<int>(n); ++i) {
    s.points.push_back(point(in));
    in.parseComma();  // POV-Ray allows a trailing comma
  }
  const PolygonOutline outline = polygonOutline(s.points);
  if (outline.closedLast)
    warn(in, o.loc,
         "the polygon's last outline is not closed (its first point is not repeated); closed "
         "it, as POV-Ray does");
  const std::string problem = polygonProblem(outline.points);
  if (!problem.empty()) {
    warn(in, o.loc, "the polygon is left out, as POV-Ray ignores it: " + problem);
    o.kind = NodeKind::Group;  // nothing: an empty group
    return;
  }
  o.shape = std::move(s);
}

// bicubic_patch { type T [flatness F] [u_steps U] [v_steps V] [accuracy A] 16 points }, or
// POV-Ray 1.5's numbers `T, [F,] U, V` (a flatness only for the old types 2 and 3, else
// 0.1). POV-Ray makes a type above 1 type 1 with a warning, needs a type, and reads
// `accuracy` without using it.
void SceneReader::readBicubicPatch(PovObject& o, TokenStream& in) {
  BicubicPatchSpec s;
  s.flatnessInWorld = true;  // POV-Ray measures flatness after the transforms
  double type = -1.0;
  auto steps = [&](const char* what) { return parseCount(in, what, BicubicPatch::kMaxSteps); };
  if (in.peek().kind == TokenKind::Number) {
    type = in.parseFloat();
    in.parseComma();
    s.flatness = 0.1;
    if (static_cast<int>(type) == 2 || static_cast<int>(type) == 3) {
      s.flatness = in.parseFloat();
      in.parseComma();
    }
    s.uSteps = steps("u_steps");
    in.parseComma();
    s.vSteps = steps("v_steps");
  } else {
    for (;;) {
      if (allowWord(in, "type")) type = in.parseFloat();
      else if (allowWord(in, "flatness")) s.flatness = in.parseFloat();
      else if (allowWord(in, "u_steps")) s.uSteps = steps("u_steps");
      else if (allowWord(in, "v_steps")) s.vSteps = steps("v_steps");
      else if (allowWord(in, "accuracy")) in.parseFloat();
      else if (allowWord(in, "uv_vectors")) {
        // The corners' texture (u, v); POV-Ray reads no keyword after them.
        for (size_t c = 0; c < 4; ++c) {
          if (c > 0) in.parseComma();
          s.uvVectors[c] = parseUv(in);
        }
        break;
      } else break;
    }
  }
  const int t = static_cast<int>(type);
  if (t < 0) in.error(o.loc, "the bicubic_patch has no type (type 0 or 1)");
  if (t > 1)
    warn(in, o.loc, "bicubic_patch type " + std::to_string(t) + " is type 1, as in POV-Ray");
  s.type = std::min(t, 1);
  if (s.flatness < 0.0) s.flatness = 0.0;  // never flat either way
  in.parseComma();
  PatchPoints points{};
  for (size_t i = 0; i < 16; ++i) {
    points[i] = point(in);
    in.parseComma();
  }
  s.points = std::make_shared<const PatchPoints>(points);
  o.shape = std::move(s);
}

// julia_fractal { <4-vector> [quaternion|hypercomplex] [FUNCTION] [max_iteration N]
// [precision P] [slice <4-vector>, D] } (the keywords in any order, the last of each
// counting): POV-Ray's rules, a max_iteration below 1 made 1 and a precision below 1 made 1
// (silently, as POV-Ray). The map is the same in both spaces, so the shape is first
// mirrored in z (as a height field).
void SceneReader::readJuliaFractal(PovObject& o, TokenStream& in) {
  static const std::map<std::string_view, JuliaFunction> kFunctions = {
      {"sqr", JuliaFunction::Sqr},
      {"cube", JuliaFunction::Cube},
      {"reciprocal", JuliaFunction::Reciprocal},
      {"exp", JuliaFunction::Exp},
      {"ln", JuliaFunction::Ln},
      {"sin", JuliaFunction::Sin},
      {"asin", JuliaFunction::Asin},
      {"cos", JuliaFunction::Cos},
      {"acos", JuliaFunction::Acos},
      {"tan", JuliaFunction::Tan},
      {"atan", JuliaFunction::Atan},
      {"sinh", JuliaFunction::Sinh},
      {"asinh", JuliaFunction::Asinh},
      {"cosh", JuliaFunction::Cosh},
      {"acosh", JuliaFunction::Acosh},
      {"tanh", JuliaFunction::Tanh},
      {"atanh", JuliaFunction::Atanh}};
  JuliaFractalSpec s;
  s.c = parseVector4(in);
  SourceLoc functionLoc = o.loc;
  for (;;) {
    const Token& t = in.peek();
    if (t.kind != TokenKind::Keyword) break;
    const std::string word(t.text());  // kept: next() moves on from t
    if (const auto f = kFunctions.find(word); f != kFunctions.end()) {
      functionLoc = in.next().loc();
      s.function = f->second;
    } else if (word == "pwr") {
      functionLoc = in.next().loc();
      s.function = JuliaFunction::Pwr;
      in.expect("(");
      s.exponent.x = in.parseFloat();
      in.expect(",");
      s.exponent.y = in.parseFloat();
      in.expect(")");
    } else if (word == "quaternion" || word == "hypercomplex") {
      in.next();
      s.algebra = word == "quaternion" ? JuliaAlgebra::Quaternion : JuliaAlgebra::Hypercomplex;
    } else if (word == "max_iteration") {
      in.next();
      s.maxIteration = static_cast<int>(std::max(1.0, std::floor(in.parseFloat())));
    } else if (word == "precision") {
      in.next();
      s.precision = std::max(1.0, in.parseFloat());
    } else if (word == "slice") {
      const SourceLoc loc = in.next().loc();
      s.slice = parseVector4(in);
      in.parseComma();
      s.distance = in.parseFloat();
      if (!(std::fabs(glm::dot(s.slice, s.slice)) >= kPovEpsilon))
        in.error(loc, "the julia_fractal's slice vector is zero");
      if (!(std::fabs(s.slice.w) >= kPovEpsilon))
        in.error(loc, "the julia_fractal's slice t component is zero");
    } else {
      break;
    }
  }
  if (s.algebra == JuliaAlgebra::Quaternion && s.function != JuliaFunction::Sqr &&
      s.function != JuliaFunction::Cube)
    in.error(functionLoc,
             "illegal function: quaternion only supports sqr and cube (POV-Ray's "
             "error)");
  o.transform.scale(Vec3(1.0, 1.0, -1.0));
  o.shape = std::move(s);
}

// sphere_sweep { linear_spline|cubic_spline|b_spline [,] N, <c>, r, ... [tolerance T] }:
// POV-Ray's parser's rules (the spline first, N read as a float and truncated, at least 2
// spheres, 4 for the cubic splines); the centres into Lucent's space. POV-Ray takes a
// negative radius; Lucent refuses it at the number.
void SceneReader::readSphereSweep(PovObject& o, TokenStream& in) {
  SphereSweepSpec s;
  if (allowWord(in, "linear_spline")) s.spline = SweepSpline::Linear;
  else if (allowWord(in, "cubic_spline")) s.spline = SweepSpline::Cubic;
  else if (allowWord(in, "b_spline")) s.spline = SweepSpline::BSpline;
  else
    in.error(in.peek().loc(),
             "the sphere_sweep's spline expected: linear_spline, cubic_spline or b_spline "
             "(POV-Ray's 'Invalid type of interpolation')");
  in.parseComma();
  const SourceLoc countLoc = in.peek().loc();
  const int n = parseCount(in, "number of spheres");
  if (n < SphereSweep::minSpheres(s.spline))
    in.error(countLoc, std::string(s.spline == SweepSpline::Linear
                                       ? "a linear_spline sphere_sweep needs 2 spheres or more"
                                       : "a cubic_spline or b_spline sphere_sweep needs 4 "
                                         "spheres or more") +
                           ", not " + std::to_string(n) +
                           " (POV-Ray's 'Too few modeling spheres')");
  for (int i = 0; i < n; ++i) {
    in.parseComma();
    SweepSphere sphere;
    sphere.center = point(in);
    in.parseComma();
    const SourceLoc radiusLoc = in.peek().loc();
    sphere.radius = in.parseFloat();
    if (sphere.radius < 0.0)
      in.error(radiusLoc, "a negative sphere_sweep radius is not supported by Lucent (radii >= 0)");
    s.spheres.push_back(sphere);
  }
  if (allowWord(in, "tolerance")) s.tolerance = in.parseFloat();
  try {
    SphereSweep check(s.spline, s.spheres);
  } catch (const std::invalid_argument& e) {
    refuseShape(o, o.loc, in,
                std::string("this sphere_sweep is not supported by Lucent (") + e.what() + ")");
    return;
  }
  o.shape = std::move(s);
}

// text { ttf "font" "string" THICKNESS, OFFSET }: the font searched as #include files are.
// Lucent's text lies from z = 0 to thickness, POV-Ray's too: after z → −z it lies from
// −thickness to 0, so the shape is first moved by the thickness along POV-Ray's z.
void SceneReader::readText(PovObject& o, TokenStream& in) {
  const Token kind = in.next();
  TextSpec s;
  SourceLoc fontLoc = in.peek().loc();
  if (isWord(kind, "internal")) {
    // POV-Ray's built-in fonts are its own font files, which its include folder holds.
    const double n = in.parseFloat();
    s.font = n == 1   ? "timrom.ttf"
             : n == 2 ? "cyrvetic.ttf"
             : n == 3 ? "crystal.ttf"
                      : "povlogo.ttf";
  } else if (isWord(kind, "ttf")) {
    s.font = in.parseString();
  } else {
    in.error(kind, "'ttf' or 'internal' expected, not " + kind.describe());
  }
  in.parseComma();
  const SourceLoc stringLoc = in.peek().loc();
  s.string = in.parseString();
  in.parseComma();
  const SourceLoc thicknessLoc = in.peek().loc();
  s.thickness = in.parseFloat();
  in.parseComma();
  const Vec3 offset = toVec3(in.parseVector());
  s.offset = Vec2(offset.x, offset.y);
  if (!(s.thickness > 0.0))
    in.error(thicknessLoc,
             "the text's thickness must be above 0 in Lucent, not " + attributeText(s.thickness));
  s.fontPath = in.findDataFile(s.font, fontLoc, {".ttf", ".TTF"}).string();
  // The same text in the same font (a macro's letters, made again at each call) is laid
  // out once: an outline is never changed after it is made.
  std::shared_ptr<TextOutline>& outline =
      textOutlines_[fmt::format("{}\n{}\n{}\n{}", s.fontPath, s.string, s.offset.x, s.offset.y)];
  if (!outline)
    outline = std::make_shared<TextOutline>(textOutline(s.fontPath, s.string, s.offset));
  if (!outline->error.empty()) {
    if (outline->error.find("UTF-8") != std::string::npos) in.error(stringLoc, outline->error);
    in.error(fontLoc, "cannot read the font '" + s.font + "': " + outline->error);
  }
  std::string missing;
  for (const PlacedGlyph& g : outline->glyphs)
    if (g.glyphIndex == 0 && missing.size() < 40)
      missing += fmt::format(" U+{:04X}", static_cast<unsigned>(g.codepoint));
  if (!missing.empty())
    warn(in, stringLoc, "the font has no glyph for" + missing + "; its missing-glyph box is shown");
  s.outline = outline;
  o.transform.translate(Vec3(0.0, 0.0, s.thickness));
  o.shape = std::move(s);
}

// smooth and water_level, after the field's source.
void SceneReader::readHeightFieldOptions(HeightFieldSpec& s, TokenStream& in) {
  for (;;) {
    if (allowWord(in, "smooth")) {
      s.smooth = true;
    } else if (isWord(in.peek(), "water_level")) {
      const SourceLoc loc = in.next().loc();
      s.waterLevel = in.parseFloat();
      if (!(s.waterLevel >= 0.0 && s.waterLevel < 1.0))
        in.error(loc,
                 "the water level must be from 0 to below 1, not " + attributeText(s.waterLevel));
    } else {
      break;
    }
  }
}

// height_field { function W, H { F } [smooth] [water_level W] }: F sampled on a W x H grid
// (primitives/height_map_function.h) where it is read, as POV-Ray does. A pigment function's height
// is its grey (POV-Ray takes the grey of its colour's channels each first stored in 16 bits: a
// height differs by at most 1/65535). POV-Ray's point is (x, y, 0) in its space, which is Lucent's
// (z = 0 either way).
void SceneReader::readFunctionHeightField(PovObject& o, TokenStream& in) {
  in.next();  // function
  HeightFieldSpec s;
  const SourceLoc wAt = in.peek().loc();
  const double w = in.parseFloat();
  in.parseComma();
  const SourceLoc hAt = in.peek().loc();
  const double h = in.parseFloat();
  // POV-Ray rounds each to the nearest whole number.
  for (const auto& [v, at, axis] : {std::tuple{w, wAt, "width"}, std::tuple{h, hAt, "height"}})
    if (!(v + 0.5 >= 2.0 && v + 0.5 < kMaxFunctionFieldSide + 1.0))
      in.error(at, fmt::format("the function height field's {} must be from 2 to {}, not {}", axis,
                               kMaxFunctionFieldSide, attributeText(v)));
  s.resolution[0] = static_cast<int>(w + 0.5);
  s.resolution[1] = static_cast<int>(h + 0.5);
  // Read as a declared function is (POV-Ray's Parse_DeclareFunction): a pigment may be given.
  const std::shared_ptr<const FunctionValue> f = in.parseFunction(true, "");
  std::shared_ptr<const FunctionValue> scalar = f;
  if (f->kind == FunctionValue::Kind::Pigment) {
    // Its grey, as a call of it: a function of x, y and z whose body takes .gray.
    auto call = std::make_shared<FnNode>();
    call->op = FnOp::Call;
    call->callee = f;
    call->member = static_cast<int>(PigmentComponent::gray);
    call->loc = f->loc;
    for (int i = 0; i < 3; ++i) {
      auto p = std::make_shared<FnNode>();
      p->op = FnOp::Param;
      p->index = i;
      p->loc = f->loc;
      call->args.push_back(p);
    }
    call->depth = 2;
    auto g = std::make_shared<FunctionValue>();
    g->loc = f->loc;
    g->params = {"x", "y", "z"};
    g->body = call;
    g->depth = f->depth + 1;
    scalar = g;
  }
  const auto compiled =
      compiledFunction(*scalar, {"x", "y", "z"}, "this height field's function", in);
  readHeightFieldOptions(s, in);
  if (!compiled) return;
  s.function = compiled->text;
  s.field = compiled->field;
  s.pigments = compiled->pigments;
  // POV-Ray makes the grid here, with the noise generator global_settings chose so far.
  for (const std::shared_ptr<PigmentFunction>& p : pigmentFunctions_)
    if (std::find(s.pigments.begin(), s.pigments.end(), p) != s.pigments.end())
      forEachTexturePattern(p->pigment, [&](PatternSpec& ps) {
        if (ps.noiseGenerator == 0) ps.noiseGenerator = global_.noiseGenerator;
      });
  s.map = sampleHeightMap(*s.field, s.resolution[0], s.resolution[1]);
  s.open = true;
  o.transform.scale(Vec3(1.0, 1.0, -1.0));
  o.shape = std::move(s);
}

// height_field { TYPE "file" [smooth] [water_level W] }: the types whose files Lucent reads
// as POV-Ray does (images/height_map_file.h). The field spans x and z from 0 to 1, the
// image's top row at z = 1 in POV-Ray's space; Lucent's has it at z = 1 in its own, so the
// shape is first mirrored in z (S·M·S of the mirror is the mirror: z = 1 lands at −1).
void SceneReader::readHeightField(PovObject& o, TokenStream& in) {
  // The types, and the extensions POV-Ray tries for each; none: one Lucent does not read.
  static const std::map<std::string_view, std::vector<std::string>> kTypes = {
      {"png", {".png", ".PNG"}},
      {"pgm", {".pgm", ".PGM"}},
      {"ppm", {".ppm", ".PPM"}},
      {"tga", {".tga", ".TGA"}},
      {"jpeg", {".jpg", ".JPG", ".jpeg", ".JPEG"}},
      {"tiff", {".tif", ".TIF", ".tiff", ".TIFF"}},
      {"gif", {".gif", ".GIF"}},
      {"iff", {}},
      {"pot", {".gif", ".GIF"}},  // POV-Ray searches a POT file as a GIF
      {"sys", {}},
      {"bmp", {}},
      {"exr", {}},
      {"hdr", {}}};
  if (isWord(in.peek(), "function")) {
    readFunctionHeightField(o, in);
    return;
  }
  const Token type = in.next();
  const auto known = type.kind == TokenKind::Keyword ? kTypes.find(type.text()) : kTypes.end();
  if (known != kTypes.end() && known->second.empty()) {
    refuseShape(o, type.loc(), in,
                "a height field from '" + std::string(type.text()) +
                    "' is not supported by Lucent (it reads png, pgm, ppm, tga, jpeg, tiff, gif "
                    "and pot images as height fields)");
    return;
  }
  if (known == kTypes.end()) in.unget();  // a file name alone: its extension says the type
  const SourceLoc fileLoc = in.peek().loc();
  HeightFieldSpec s;
  s.src = in.parseString();
  s.path = in.findDataFile(s.src, fileLoc,
                           known != kTypes.end() ? known->second : std::vector<std::string>{})
               .string();
  // A POT file is told from a GIF by its name, as the XML's height field tells it.
  const bool potFile = isPotFileName(s.path);
  if (known != kTypes.end() && (known->first == "pot") != potFile)
    in.error(fileLoc, potFile ? "a file named .pot is read as a POT file: write 'pot', not '" +
                                    std::string(known->first) + "'"
                              : "a POT file must be named .pot (Lucent tells it from a GIF by "
                                "its name)");
  try {
    s.map = readHeightMapFile(s.path);
  } catch (const std::exception& e) {
    in.error(fileLoc, "cannot read the height field's image '" + s.src + "': " + e.what());
  }
  // The image's gamma and premultiplied, as after any image's name: POV-Ray reads a height
  // field's values as stored unless a gamma is written.
  for (;;) {
    if (isWord(in.peek(), "gamma")) {
      const Token k = in.next();
      const bool srgb = isWord(in.peek(), "srgb");
      const double g = srgb ? (in.next(), 1.0) : in.parseFloat();
      if (!(g > 0.0))
        in.error(k, "gamma " + attributeText(g) + ": an image's gamma must be above 0");
      if (srgb || g != 1.0)
        warn(in, k.loc(),
             std::string("the image's gamma ") + (srgb ? "srgb" : attributeText(g)) +
                 " is not read (Lucent reads a height field's values as stored, as POV-Ray "
                 "does without a gamma)");
    } else if (allowWord(in, "premultiplied")) {
      in.parseFloat();
    } else {
      break;
    }
  }
  readHeightFieldOptions(s, in);
  const uint16_t top = *std::max_element(s.map->values.begin(), s.map->values.end());
  if (!(top / 65536.0 > s.waterLevel))
    in.error(fileLoc, "nothing of the height field lies above the water level " +
                          attributeText(s.waterLevel));
  // POV-Ray's height field has neither walls nor a floor (closed again within a CSG:
  // closeForCsg).
  s.open = true;
  o.transform.scale(Vec3(1.0, 1.0, -1.0));
  o.shape = std::move(s);
}

// The triangles of a mesh or mesh2 as read: three corners each, with their normals when
// any triangle has them, and their uvs when any has them (the others' (0, 0), as POV-Ray's).
struct MeshBuild {
  std::vector<std::array<Vec3, 3>> corners;
  std::vector<std::optional<std::array<Vec3, 3>>> normals;
  std::vector<std::optional<std::array<Vec2, 3>>> uvs;
  // Each triangle's texture of its own (an index into `textures`), or -1 for the mesh's:
  // a mesh triangle's `texture { T }`, a mesh2 face's index into its texture_list.
  std::vector<int> texture;
  std::vector<PovTexture> textures;
  std::vector<SourceLoc> textureLocs;
  // A mesh's triangles name declared textures: one entry per declaration (POV-Ray hashes
  // them by identity), whatever the number of triangles.
  std::map<std::pair<std::string, uint64_t>, int> named;

  int addTexture(PovTexture t, const SourceLoc& at) {
    if (!t.name.empty()) {
      const auto [it, added] =
          named.try_emplace({t.name, t.declaration}, static_cast<int>(textures.size()));
      if (!added) return it->second;
    }
    textures.push_back(std::move(t));
    textureLocs.push_back(at);
    return static_cast<int>(textures.size()) - 1;
  }
};

namespace {

// The triangles as read, in order, each with its own three positions (a corner's normal
// belongs to the triangle): a mesh camera's faces, and what the mesh is built from.
std::shared_ptr<const MeshData> faces(const MeshBuild& b) {
  auto d = std::make_shared<MeshData>();
  bool anyNormals = false, anyUvs = false;
  for (const auto& n : b.normals) anyNormals |= n.has_value();
  for (const auto& uv : b.uvs) anyUvs |= uv.has_value();
  for (size_t t = 0; t < b.corners.size(); ++t) {
    const auto& p = b.corners[t];
    const uint32_t first = static_cast<uint32_t>(d->positions.size());
    const Vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
    for (size_t k = 0; k < 3; ++k) {
      d->positions.push_back(lucentFromPov(p[k]));
      if (anyNormals) {
        const Vec3 n = b.normals[t] ? (*b.normals[t])[k] : face;
        d->normals.push_back(glm::length(n) > 0.0 ? glm::normalize(lucentFromPov(n)) : Vec3(0.0));
      }
      if (anyUvs) d->uvs.push_back(b.uvs[t] ? (*b.uvs[t])[k] : Vec2(0.0));
    }
    d->triangles.push_back({first, first + 1, first + 2});
  }
  return d;
}

// The mesh Lucent draws: the faces repaired (the repair pairs their edges by position).
std::shared_ptr<const MeshData> meshData(const MeshData& faces) {
  auto d = std::make_shared<MeshData>(faces);
  finishMesh(*d);
  return d;
}

// POV-Ray drops a triangle whose corners are (nearly) on one line.
bool degenerate(const std::array<Vec3, 3>& p) {
  return glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) < kPovEpsilon;
}

// A vertex normal of a smooth triangle: POV-Ray takes <1, 0, 0> for a zero one, with a
// warning.
Vec3 meshNormal(TokenStream& in, const Vec3& n, const SourceLoc& at, bool& warned) {
  if (glm::length(n) > 0.0) return n;
  if (!warned) in.warning(at, "a mesh normal of length 0 is taken as <1, 0, 0>, as POV-Ray does");
  warned = true;
  return Vec3(1.0, 0.0, 0.0);
}

}  // namespace

// Reads a triangle's `uv_vectors` and its texture: `texture { T }`, or `texture_list { A,
// B, C }` (a texture per corner, which POV-Ray blends across the triangle: refused unless
// the three are one). False when a texture was refused.
bool SceneReader::readMeshTriangleExtras(PovObject& o, TokenStream& in,
                                         std::optional<std::array<Vec2, 3>>& uv, MeshBuild& b,
                                         int& texture) {
  bool ok = true;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return ok;
    if (isWord(t, "uv_vectors")) {
      std::array<Vec2, 3> v{};
      for (int k = 0; k < 3; ++k) {
        if (k > 0) in.parseComma();
        v[static_cast<size_t>(k)] = parseUv(in);
      }
      uv = v;
    } else if (isWord(t, "texture") || isWord(t, "texture_list")) {
      // Declared textures only, as POV-Ray reads them: `texture { T }`, `texture_list { A, B, C }`.
      const bool one = isWord(t, "texture");
      in.expect("{");
      std::array<const TextureItem*, 3> items{};
      std::string name;  // the first's, naming the material of a declared texture
      for (size_t k = 0; k < (one ? 1 : 3); ++k) {
        if (k > 0) in.parseComma();
        const Token id = in.peek();
        items[k] = use<TextureItem>(id, in);
        if (!items[k])
          in.error(id, "a mesh triangle's " + std::string(t.text()) + " takes " +
                           (one ? "a declared texture" : "three declared textures") +
                           " (as in POV-Ray), not " + id.describe());
        if (k == 0 && !id.element) name = std::string(id.text());
        in.next();
      }
      in.expect("}");
      if (one || (items[0] == items[1] && items[0] == items[2])) {
        PovTexture declared = items[0]->texture;
        declared.name = name;
        texture = b.addTexture(std::move(declared), t.loc());
      } else {
        refuse(o, t.loc(), in,
               "a texture per corner of a mesh triangle ('texture_list' of different textures, "
               "which POV-Ray blends across the triangle) is not supported by Lucent (give the "
               "triangle one texture)");
        ok = false;
      }
    } else {
      in.error(t, "unexpected " + t.describe() + " in a mesh triangle");
    }
  }
}

// mesh { triangle { A, B, C } smooth_triangle { A, NA, B, NB, C, NC } [inside_vector V] }
void SceneReader::readMesh(PovObject& o, TokenStream& in) {
  MeshBuild b;
  bool ok = true, insideVector = false, warned = false;
  for (;;) {
    const Token t = in.next();
    const bool smooth = isWord(t, "smooth_triangle");
    if (isWord(t, "triangle") || smooth) {
      in.expect("{");
      std::array<Vec3, 3> p{}, n{};
      for (int k = 0; k < 3; ++k) {
        if (k > 0) in.parseComma();
        p[static_cast<size_t>(k)] = toVec3(in.parseVector());
        if (smooth) {
          in.parseComma();
          n[static_cast<size_t>(k)] = meshNormal(in, toVec3(in.parseVector()), t.loc(), warned);
        }
      }
      std::optional<std::array<Vec2, 3>> uv;
      int texture = -1;
      ok = readMeshTriangleExtras(o, in, uv, b, texture) && ok;
      if (degenerate(p)) continue;
      b.corners.push_back(p);
      b.texture.push_back(texture);
      // A smooth triangle with three equal normals is flat in POV-Ray.
      const bool flat = !smooth || (glm::length(n[0] - n[1]) < kPovEpsilon &&
                                    glm::length(n[0] - n[2]) < kPovEpsilon);
      b.normals.push_back(flat ? std::nullopt : std::optional<std::array<Vec3, 3>>(n));
      b.uvs.push_back(uv);
    } else if (isWord(t, "inside_vector")) {
      in.parseVector();
      insideVector = true;
    } else {
      in.unget();
      break;
    }
  }
  if (!ok) return;
  finishMeshShape(o, in, b, insideVector);
}

// mesh2 { vertex_vectors { N, V... } [normal_vectors { N, V... }] [uv_vectors { N, UV... }]
// face_indices { N, <a, b, c>... } [normal_indices { N, <a, b, c>... }] [uv_indices {...}]
// [inside_vector V] }. Without normal_indices, face_indices index the normals too. With a
// texture_list { N, texture {...}... }, a face may name its texture: `<a, b, c>, T`, or one
// per corner `<a, b, c>, T1, T2, T3` (refused unless the three are one).
void SceneReader::readMesh2(PovObject& o, TokenStream& in) {
  std::vector<Vec3> vertices, normals;
  std::vector<Vec2> uvVectors;
  std::vector<std::array<long, 3>> faces, normalFaces, uvFaces;
  std::vector<int> faceTextures;  // per face: an index into b.textures, or -1
  MeshBuild b;
  bool insideVector = false;
  std::optional<SourceLoc> perCorner;  // the first face with a texture per corner
  // `NAME { N, item... }`: N items read by `item`.
  auto list = [&](const char* name, auto&& item) {
    in.expect("{");
    const int n = parseCount(in, (std::string("number of ") + name).c_str());
    for (int i = 0; i < n; ++i) {
      in.parseComma();
      item();
    }
    in.parseComma();
    in.expect("}");
  };
  auto indices = [&](std::vector<std::array<long, 3>>& out) {
    return [&in, &out] {
      const Vec3 v = toVec3(in.parseVector());
      out.push_back({static_cast<long>(v.x), static_cast<long>(v.y), static_cast<long>(v.z)});
    };
  };
  for (;;) {
    const Token t = in.next();
    if (isWord(t, "vertex_vectors")) {
      list("vertex_vectors", [&] { vertices.push_back(toVec3(in.parseVector())); });
    } else if (isWord(t, "normal_vectors")) {
      bool warned = false;
      list("normal_vectors",
           [&] { normals.push_back(meshNormal(in, toVec3(in.parseVector()), t.loc(), warned)); });
    } else if (isWord(t, "uv_vectors")) {
      list("uv_vectors", [&] { uvVectors.push_back(parseUv(in)); });
    } else if (isWord(t, "face_indices")) {
      readFaceIndices(in, b.textures.size(), faces, faceTextures, perCorner);
    } else if (isWord(t, "normal_indices")) {
      list("normal_indices", indices(normalFaces));
    } else if (isWord(t, "uv_indices")) {
      list("uv_indices", indices(uvFaces));
    } else if (isWord(t, "texture_list")) {
      if (!b.textures.empty()) in.error(t, "the mesh2 has a second texture_list");
      list("texture_list", [&] {
        const Token word = in.next();
        if (!isWord(word, "texture"))
          in.error(word, "expected a texture in the mesh2's texture_list, not " + word.describe());
        b.textures.push_back(readTexture(in, defaultTexture()));
        b.textureLocs.push_back(word.loc());
      });
    } else if (isWord(t, "inside_vector")) {
      in.parseVector();
      insideVector = true;
    } else {
      in.unget();
      break;
    }
  }
  if (vertices.empty() || faces.empty())
    in.error(o.loc, "the mesh2 needs vertex_vectors and face_indices");
  if (perCorner) {
    refuse(o, *perCorner, in,
           "a texture per corner of a mesh2 face (three different texture indices, which "
           "POV-Ray blends across the face) is not supported by Lucent (give the face one "
           "texture)");
    return;
  }
  const std::vector<std::array<long, 3>>& nf = normalFaces.empty() ? faces : normalFaces;
  if (!normals.empty() && nf.size() != faces.size())
    in.error(o.loc, "the mesh2 has " + std::to_string(nf.size()) + " normal_indices for " +
                        std::to_string(faces.size()) + " faces");
  auto index = [&](long i, size_t count, const char* what) {
    if (i < 0 || static_cast<size_t>(i) >= count)
      in.error(o.loc, "the mesh2's " + std::string(what) + " index " + std::to_string(i) +
                          " is outside its " + std::to_string(count) + " vectors");
    return static_cast<size_t>(i);
  };
  for (size_t f = 0; f < faces.size(); ++f) {
    std::array<Vec3, 3> p{};
    for (size_t k = 0; k < 3; ++k) p[k] = vertices[index(faces[f][k], vertices.size(), "vertex")];
    if (degenerate(p)) continue;
    b.corners.push_back(p);
    b.texture.push_back(faceTextures[f]);
    std::optional<std::array<Vec3, 3>> n;
    if (!normals.empty()) {
      std::array<Vec3, 3> v{};
      for (size_t k = 0; k < 3; ++k) v[k] = normals[index(nf[f][k], normals.size(), "normal")];
      if (glm::length(v[0] - v[1]) >= kPovEpsilon || glm::length(v[0] - v[2]) >= kPovEpsilon) n = v;
    }
    b.normals.push_back(n);
    std::optional<std::array<Vec2, 3>> uv;
    const std::vector<std::array<long, 3>>& uf = uvFaces.empty() ? faces : uvFaces;
    if (!uvVectors.empty() && f < uf.size()) {
      std::array<Vec2, 3> v{};
      for (size_t k = 0; k < 3; ++k) v[k] = uvVectors[index(uf[f][k], uvVectors.size(), "uv")];
      uv = v;
    }
    b.uvs.push_back(uv);
  }
  finishMeshShape(o, in, b, insideVector);
}

// face_indices { N, <a, b, c> [, T [, T2, T3]]... }: each face with the texture indices
// that follow it (POV-Ray reads each float after a face as one, up to three), checked
// against the texture_list read before (`textures` of them). The first face with three
// that differ sets perCorner to where its indices are.
void SceneReader::readFaceIndices(TokenStream& in, size_t textures,
                                  std::vector<std::array<long, 3>>& faces,
                                  std::vector<int>& faceTextures,
                                  std::optional<SourceLoc>& perCorner) {
  in.expect("{");
  const int n = parseCount(in, "number of face_indices");
  // A face written as a vector identifier is known only once read: kept for the next face.
  std::optional<Value> next;
  for (int i = 0; i < n; ++i) {
    in.parseComma();
    const Value face = next ? *next : in.parseExpression();
    next.reset();
    if (!face.isNumeric()) in.error(in.current(), "expected a face's three vertex indices");
    const int terms = face.terms();
    const Vec3 v = terms == 1 ? Vec3(face.v[0]) : Vec3(face.v[0], face.v[1], face.v[2]);
    faces.push_back({static_cast<long>(v.x), static_cast<long>(v.y), static_cast<long>(v.z)});
    std::array<long, 3> own{-1, -1, -1};
    const SourceLoc indicesAt = in.peek().loc();
    int count = 0;
    for (; count < 3; ++count) {
      in.parseComma();
      if (in.peek().is("}") || in.peek().is("<")) break;
      const SourceLoc at = in.peek().loc();
      const Value index = in.parseExpression();
      if (index.terms() != 1) {
        next = index;
        break;
      }
      own[static_cast<size_t>(count)] = static_cast<long>(index.v[0]);
      if (own[static_cast<size_t>(count)] < 0 ||
          static_cast<size_t>(own[static_cast<size_t>(count)]) >= textures)
        in.error(at, "the face's texture index " + std::to_string(own[static_cast<size_t>(count)]) +
                         " is outside the mesh2's texture_list of " + std::to_string(textures) +
                         " textures");
    }
    for (int k = 1; k < count; ++k)
      if (own[static_cast<size_t>(k)] != own[0] && !perCorner) perCorner = indicesAt;
    faceTextures.push_back(static_cast<int>(own[0]));
  }
  if (next) in.error(in.current(), "more face_indices than the " + std::to_string(n) + " given");
  in.parseComma();
  in.expect("}");
}

// The mesh's data made and repaired; POV-Ray's solidity (inside_vector) compared with
// Lucent's (a closed, consistently oriented mesh is a solid).
void SceneReader::finishMeshShape(PovObject& o, TokenStream& in, const MeshBuild& b,
                                  bool insideVector) {
  if (b.corners.empty()) in.error(o.loc, "the " + o.keyword + " has no triangle (of some area)");
  o.faces = faces(b);
  if (std::any_of(b.texture.begin(), b.texture.end(), [](int t) { return t >= 0; })) {
    splitByTexture(o, in, b, insideVector);
    return;
  }
  MeshSpec s;
  try {
    s.data = meshData(*o.faces);
  } catch (const std::exception& e) {
    in.error(o.loc, "the " + o.keyword + "'s triangles: " + e.what());
  }
  if (s.data->closed && !insideVector)
    warn(in, o.loc,
         "the " + o.keyword +
             " is closed, so Lucent takes it as a solid; POV-Ray's has no inside without "
             "inside_vector (it differs inside CSG and refractive objects)");
  else if (!s.data->closed && insideVector)
    warn(in, o.loc,
         "the " + o.keyword +
             " has an inside_vector but is not closed: Lucent takes it as a surface, not a solid");
  o.shape = std::move(s);
}

// A mesh whose triangles have textures of their own: a union of meshes, one per texture
// and one of the triangles that take the mesh's (POV-Ray's triangle texture wins over the
// object's), each texture in the mesh's own space as POV-Ray transforms them with it.
void SceneReader::splitByTexture(PovObject& o, TokenStream& in, const MeshBuild& b,
                                 bool insideVector) {
  std::vector<MeshBuild> parts(b.textures.size() + 1);
  for (size_t f = 0; f < b.corners.size(); ++f) {
    MeshBuild& p = parts[static_cast<size_t>(b.texture[f] + 1)];
    p.corners.push_back(b.corners[f]);
    p.normals.push_back(b.normals[f]);
    p.uvs.push_back(b.uvs[f]);
  }
  std::vector<PovObject> children;
  bool closedPart = false, openPart = false;
  for (size_t g = 0; g < parts.size(); ++g) {
    if (parts[g].corners.empty()) continue;
    PovObject part;
    part.keyword = o.keyword;
    part.loc = o.loc;
    MeshSpec s;
    try {
      s.data = meshData(*faces(parts[g]));
    } catch (const std::exception& e) {
      in.error(o.loc, "the " + o.keyword + "'s triangles: " + e.what());
    }
    (s.data->closed ? closedPart : openPart) = true;
    part.shape = std::move(s);
    if (g > 0) {
      part.texture = b.textures[g - 1];
      part.textureLoc = b.textureLocs[g - 1];
    }
    children.push_back(std::move(part));
  }
  if (closedPart && !insideVector)
    warn(in, o.loc,
         "a part of the " + o.keyword +
             " of one texture is closed, so Lucent takes it as a solid; POV-Ray's mesh has no "
             "inside without inside_vector (it differs inside CSG and refractive objects)");
  else if (insideVector && openPart)
    warn(in, o.loc,
         "the " + o.keyword +
             " has an inside_vector, but Lucent draws it as one mesh per texture of its "
             "triangles and those that are not closed as surfaces, not solids (it differs "
             "inside CSG and refractive objects)");
  o.kind = NodeKind::Union;
  o.shape = std::nullopt;
  o.nodes += children.size();
  o.depth = 2;
  o.children.edit() = std::move(children);
}

}  // namespace lucent::sdl
