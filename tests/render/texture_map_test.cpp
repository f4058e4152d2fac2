// Maps and lists of whole textures (pigment maps, block patterns' lists of pigments,
// averages) and averages of normals: colours at chosen points against hand-computed
// blends, the nested placements composing with the enclosing one, and see-through.
#include "render/patterns/normal_perturbation.h"
#include "render/texture.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace lucent;

namespace {

const Color kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1);

TextureMapEntry colourEntry(double at, const Color& c, const FilterTransmit& ft = {}) {
  TextureMapEntry e;
  e.at = at;
  e.color = {c, ft};
  return e;
}

TextureMapEntry textureEntry(double at, const Texture& t) {
  TextureMapEntry e;
  e.at = at;
  e.texture = t;
  return e;
}

CheckerTexture checker(const Color& a, const Color& b) {
  CheckerTexture c;
  c.color1 = a;
  c.color2 = b;
  return c;
}

// A pattern placed by `transform` (pattern → object), as the parser's transform attribute.
Mat4 placed(const Mat4& transform) { return glm::inverse(transform); }

PigmentColor at(const Texture& t, const Vec3& p) { return pigmentAt(t, p, Vec3(0.0)); }

void checkColour(const Color& got, const Color& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-6));
}

}  // namespace

TEST_CASE("pigment map: the two entries around the value blend, a texture entry at the point",
          "[render][texture][pigment-map]") {
  PatternTexture t;
  t.pattern.type = PatternType::gradient;
  t.pattern.axis = Vec3(1, 0, 0);
  t.pigments = {colourEntry(0.0, kRed), textureEntry(1.0, checker(kBlue, kGreen))};
  // x = 0.25: a quarter of the way from red to the checker, whose cell (0, 0, 0) is blue.
  checkColour(at(t, Vec3(0.25, 0.5, 0.5)).rgb, Color(0.75f, 0.0f, 0.25f));
  // y = 1.5: the checker's cell (0, 1, 0) is green.
  checkColour(at(t, Vec3(0.5, 1.5, 0.5)).rgb, Color(0.5f, 0.5f, 0.0f));
  // At an entry's own value, that entry alone.
  checkColour(at(t, Vec3(0.0, 0.5, 0.5)).rgb, kRed);
}

TEST_CASE("pigment map: a nested texture's placement composes with the pattern's",
          "[render][texture][pigment-map]") {
  PatternTexture t;
  t.pattern.type = PatternType::gradient;
  t.pattern.placement.patternFromObject = placed(glm::scale(Mat4(1.0), Vec3(2.0)));
  CheckerTexture inner = checker(kBlue, kGreen);
  t.pigments = {textureEntry(0.0, inner)};
  // The checker sees the pattern's point p/2: (1.5, 0.5, 0.5) is in its cell 0.
  checkColour(at(t, Vec3(1.5, 0.5, 0.5)).rgb, kBlue);
  // Its own scale 0.25 on top: p/2/0.25 = (3, 1, 1), cell 5, odd.
  inner.placement.patternFromObject = placed(glm::scale(Mat4(1.0), Vec3(0.25)));
  t.pigments = {textureEntry(0.0, inner)};
  checkColour(at(t, Vec3(1.5, 0.5, 0.5)).rgb, kGreen);
}

TEST_CASE("block patterns' lists: the cell's texture at the block pattern's point",
          "[render][texture][pigment-map]") {
  // A checker of cubes of edge 2 whose first cell holds a grey gradient along x: the
  // gradient sees p / 2 (the scale is POV-Ray's `scale` of the whole pigment).
  CheckerTexture c;
  c.scale = 2.0;
  PatternTexture grey;
  grey.pattern.type = PatternType::gradient;
  grey.pattern.axis = Vec3(1, 0, 0);
  c.pigments = {textureEntry(0.0, grey), colourEntry(0.0, kRed)};
  checkColour(at(c, Vec3(0.5, 0.1, 0.1)).rgb, Color(0.25f));
  checkColour(at(c, Vec3(2.5, 0.1, 0.1)).rgb, kRed);

  // A hexagon of three plain entries shows each cell as the hexagon of those colours does.
  HexagonTexture h, colours;
  h.pigments = {colourEntry(0, kRed), colourEntry(0, kGreen), colourEntry(0, kBlue)};
  colours.spec.colors[0] = kRed;
  colours.spec.colors[1] = kGreen;
  colours.spec.colors[2] = kBlue;
  for (const Vec3& p : {Vec3(0.0), Vec3(1.2, 0.0, 0.3), Vec3(0.4, 0.0, 1.3), Vec3(2.0, 5.0, 0.8)})
    checkColour(at(h, p).rgb, at(colours, p).rgb);
  // A brick of a colour (the mortar) and a checker (the bricks, at the brick's point): the
  // mortar where the brick of colours has color1, the checker's cell elsewhere.
  BrickTexture b, plain;
  b.pigments = {colourEntry(0, kRed), textureEntry(0, checker(kGreen, kBlue))};
  plain.spec.color1 = kRed;
  plain.spec.color2 = kGreen;
  int mortar = 0, bricks = 0;
  for (const Vec3& p : {Vec3(0.1, 0.1, 0.1), Vec3(2.5, 1.5, 1.5), Vec3(3.5, 0.2, 1.5),
                        Vec3(8.1, 1.5, 2.0), Vec3(4.0, 2.9, 0.1)}) {
    const bool isMortar = at(plain, p).rgb == kRed;
    (isMortar ? mortar : bricks)++;
    const Color cellColour =
        (static_cast<int>(std::floor(p.x)) + static_cast<int>(std::floor(p.y)) +
         static_cast<int>(std::floor(p.z))) %
                    2 ==
                0
            ? kGreen
            : kBlue;
    checkColour(at(b, p).rgb, isMortar ? kRed : cellColour);
  }
  CHECK(mortar > 0);
  CHECK(bricks > 0);
}

TEST_CASE("average: colours, filters and transmits weighted by the entries' weights",
          "[render][texture][pigment-map]") {
  AverageTexture a;
  a.entries = {colourEntry(1.0, kRed), colourEntry(3.0, kBlue, {0.0f, 0.4f})};
  const PigmentColor c = at(a, Vec3(0.3, 0.2, 0.1));
  checkColour(c.rgb, Color(0.25f, 0.0f, 0.75f));
  CHECK(c.ft.filter == 0.0f);
  CHECK(c.ft.transmit == Approx(0.3f));
  // An average of one checker placed by the average's transform: cubes of edge 0.5.
  AverageTexture placedAverage;
  placedAverage.placement.patternFromObject = placed(glm::scale(Mat4(1.0), Vec3(0.5)));
  placedAverage.entries = {textureEntry(2.0, checker(kBlue, kGreen))};
  checkColour(at(placedAverage, Vec3(0.75, 0.25, 0.25)).rgb, kGreen);
}

TEST_CASE("maps and lists are see-through where an entry is", "[render][texture][pigment-map]") {
  PatternTexture t;
  t.pattern.type = PatternType::gradient;
  t.pigments = {colourEntry(0.0, kRed), textureEntry(1.0, checker(kBlue, kGreen))};
  CHECK_FALSE(textureSeeThrough(t));
  CheckerTexture clear = checker(kBlue, kGreen);
  clear.ft2.transmit = 0.5f;
  t.pigments[1] = textureEntry(1.0, clear);
  CHECK(textureSeeThrough(t));
  AverageTexture a;
  a.entries = {colourEntry(1.0, kRed, {0.2f, 0.0f})};
  CHECK(textureSeeThrough(a));
  // Blended as the colour: halfway between opaque red and the checker's transmit 0.5.
  const PigmentColor c = at(t, Vec3(0.5, 0.5, 1.5));
  CHECK(c.ft.transmit == Approx(0.25f));
  CHECK_FALSE(textureHoldsImage(t));
  t.pigments[0].texture = ImageTexture{};
  CHECK(textureHoldsImage(t));
}

TEST_CASE("average of normals: the weighted mean of the entries' bent normals, normalised",
          "[render][patterns][normal]") {
  NormalSpec bumps;
  bumps.pattern.type = PatternType::bumps;
  bumps.depth = 0.6;
  NormalSpec ripples;
  ripples.pattern.type = PatternType::ripples;
  ripples.depth = 0.8;
  const Vec3 p(0.3, 0.7, -0.2), n = glm::normalize(Vec3(0.2, 1.0, 0.1));

  NormalSpec average;
  average.average = {{2.0, bumps}, {1.0, ripples}};
  const Vec3 want =
      glm::normalize(2.0 * perturbNormal(bumps, p, n) + 1.0 * perturbNormal(ripples, p, n));
  const Vec3 got = perturbNormal(average, p, n);
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-12));

  // An average placed by scale(2) holding one unplaced bumps is bumps placed by scale(2).
  NormalSpec scaledAverage;
  scaledAverage.pattern.placement.patternFromObject = placed(glm::scale(Mat4(1.0), Vec3(2.0)));
  scaledAverage.average = {{1.0, bumps}};
  NormalSpec scaledBumps = bumps;
  scaledBumps.pattern.placement.patternFromObject =
      scaledAverage.pattern.placement.patternFromObject;
  const Vec3 a = perturbNormal(scaledAverage, p, n), b = perturbNormal(scaledBumps, p, n);
  for (int i = 0; i < 3; ++i) CHECK(a[i] == Approx(b[i]).margin(1e-12));
  CHECK(glm::length(a - n) > 1e-3);  // it did bend
}
