// <text>: the layout against DejaVu Sans' own tables (the numbers below were read from the
// font file's hmtx, glyf and kern tables by a separate reader, not through FreeType), hit
// distances against the outline's curves solved in long double, holes, caps, fill rules,
// damaged fonts and a text in CSG.
#include "shape_checks.h"

#include "lang/parser.h"
#include "primitives/text.h"
#include "primitives/text_outline.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

using namespace lucent;
using namespace lucent::test;
using LD = long double;

namespace {

const std::string kFont = defaultFontFile();
constexpr double kEm = 2048.0;  // DejaVu Sans' units per em

std::shared_ptr<Text> makeText(const TextOutline& o, double thickness) {
  std::vector<std::vector<PrismContour>> glyphs;
  for (const PlacedGlyph& g : o.glyphs) glyphs.push_back(g.contours);
  return std::make_shared<Text>(glyphs, thickness);
}

// The x where the horizontal line y = y0 meets the outlines, each segment's polynomial
// solved in long double (quadratics in closed form, lines directly; DejaVu has no cubics).
std::vector<LD> lineCrossingsX(const TextOutline& o, LD y0) {
  std::vector<LD> xs;
  for (const PlacedGlyph& g : o.glyphs)
    for (const PrismContour& c : g.contours)
      for (const PrismSegment& s : c) {
        REQUIRE(s.degree <= 2);
        LD a, b, cc;  // y(s) - y0 = a s² + b s + cc
        const LD y[3] = {s.p[0].y, s.p[1].y, s.degree == 2 ? (LD)s.p[2].y : 0};
        if (s.degree == 1) {
          a = 0;
          b = y[1] - y[0];
          cc = y[0] - y0;
        } else {
          a = y[0] - 2 * y[1] + y[2];
          b = 2 * (y[1] - y[0]);
          cc = y[0] - y0;
        }
        std::vector<LD> roots;
        if (std::fabs(a) < 1e-30L) {
          if (b != 0) roots.push_back(-cc / b);
        } else {
          const LD disc = b * b - 4 * a * cc;
          if (disc >= 0) {
            const LD q = -0.5L * (b + (b < 0 ? -1 : 1) * std::sqrt(disc));
            roots.push_back(q / a);
            if (q != 0) roots.push_back(cc / q);
          }
        }
        for (LD r : roots) {
          if (r < 0 || r > 1) continue;
          LD x;
          if (s.degree == 1) x = s.p[0].x + r * ((LD)s.p[1].x - s.p[0].x);
          else x = (1 - r) * (1 - r) * s.p[0].x + 2 * r * (1 - r) * s.p[1].x + r * r * s.p[2].x;
          xs.push_back(x);
        }
      }
  std::sort(xs.begin(), xs.end());
  return xs;
}

}  // namespace

TEST_CASE("text: glyphs placed by the font's advances, bearings and kerning as POV-Ray places them",
          "[primitives][text]") {
  // hmtx (advance, lsb): A (1401, 16), V (1401, 16), T (1251, -6), o (1253, 113);
  // glyf xMin equals lsb for each; kern: A V -131, T o -348, none for V T.
  const TextOutline o = textOutline(kFont, "AVTo", Vec2(0.0));
  REQUIRE(o.error.empty());
  REQUIRE(o.glyphs.size() == 4);
  CHECK(o.glyphs[0].origin.x == Approx(-16 / kEm).epsilon(1e-15));
  CHECK(o.glyphs[1].origin.x == Approx((1401 - 16 - 131) / kEm).epsilon(1e-15));
  CHECK(o.glyphs[1].kerning == Approx(-131 / kEm).epsilon(1e-15));
  CHECK(o.glyphs[2].origin.x == Approx((1401 - 16 - 131 + 1401) / kEm).epsilon(1e-15));
  CHECK(o.glyphs[2].kerning == 0.0);
  CHECK(o.glyphs[3].origin.x == Approx((1401 - 16 - 131 + 1401 + 1251 - 348) / kEm).epsilon(1e-15));
  for (const PlacedGlyph& g : o.glyphs) CHECK(g.origin.y == 0.0);
  CHECK(o.glyphs[3].advance == Approx(1253 / kEm).epsilon(1e-15));
  // The first glyph's leftmost point is at x = 0; A stands on the baseline y = 0.
  const auto t = makeText(o, 1.0);
  CHECK(t->bounds().lo.x == Approx(0.0).margin(1e-15));
  CHECK(t->bounds().lo.y == Approx(-29 / kEm).epsilon(1e-12));  // o dips below the baseline
  CHECK(t->bounds().hi.y == Approx(1493 / kEm).epsilon(1e-12));
  CHECK(t->bounds().lo.z == 0.0);
  CHECK(t->bounds().hi.z == 1.0);

  // offset moves the pen after every character, the first included.
  const TextOutline off = textOutline(kFont, "AVTo", Vec2(0.25, -0.125));
  REQUIRE(off.glyphs.size() == 4);
  for (size_t i = 0; i < 4; ++i) {
    CHECK(off.glyphs[i].origin.x == Approx(o.glyphs[i].origin.x + 0.25 * i).epsilon(1e-14));
    CHECK(off.glyphs[i].origin.y == Approx(-0.125 * i).epsilon(1e-14));
  }
  // A space draws nothing and advances by its 651 units.
  const TextOutline sp = textOutline(kFont, "o o", Vec2(0.0));
  REQUIRE(sp.glyphs.size() == 3);
  CHECK(sp.glyphs[1].contours.empty());
  CHECK(sp.glyphs[2].origin.x == Approx((1253 - 113 + 651) / kEm).epsilon(1e-15));
}

TEST_CASE(
    "text: holes of o, e and 8 and every glyph of printable ASCII by the even-odd rule equal the "
    "nonzero rule",
    "[primitives][text]") {
  // TrueType fills by the nonzero rule, POV-Ray (Inside_Glyph) and the Prism by even-odd:
  // FreeType's rasteriser finds no pixel where the two differ in DejaVu Sans.
  for (char32_t c = 0x21; c < 0x7F; ++c) {
    INFO("character " << static_cast<int>(c));
    CHECK(fillRuleDifference(kFont, c, 96) == 0);
  }
  const TextOutline o = textOutline(kFont, "o8e", Vec2(0.0));
  REQUIRE(o.error.empty());
  CHECK_FALSE(o.evenOdd);  // the font's own flag: nonzero
  CHECK(o.glyphs[0].contours.size() == 2);
  CHECK(o.glyphs[1].contours.size() == 3);
  CHECK(o.glyphs[2].contours.size() == 2);
}

TEST_CASE("text: a ray through the hole of o misses, one through its ring hits the front cap",
          "[primitives][text]") {
  // o: xMin 113, xMax 1141, yMin -29, yMax 1147; placed first, so shifted by -113.
  const TextOutline o = textOutline(kFont, "o", Vec2(0.0));
  const auto t = makeText(o, 0.5);
  const double cx = (1141 - 113) / 2.0 / kEm, cy = (1147 - 29) / 2.0 / kEm;
  Hit h;
  CHECK_FALSE(t->intersect(Ray(Vec3(cx, cy, -2), Vec3(0, 0, 1)), h));
  CHECK_FALSE(t->inside(Vec3(cx, cy, 0.25)));
  // The ring at the left, 40 units in from the leftmost point.
  const Ray ring(Vec3(40 / kEm, cy, -2), Vec3(0, 0, 1));
  REQUIRE(t->intersect(ring, h));
  CHECK(h.t == Approx(2.0).epsilon(1e-15));  // the front face z = 0
  SurfaceInfo s = t->surface(ring, h);
  CHECK(s.ng.z == Approx(-1.0));
  CrossingList cl;
  t->crossings(ring, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[1].hit.t == Approx(2.5).epsilon(1e-15));  // the back face z = thickness
  CHECK(t->surface(ring, cl.items[1].hit).ng.z == Approx(1.0));
  CHECK(t->inside(Vec3(40 / kEm, cy, 0.25)));
}

TEST_CASE("text: side hits along a line through several glyphs match the outline's curves",
          "[primitives][text]") {
  const TextOutline o = textOutline(kFont, "Lucent 8oe", Vec2(0.0));
  REQUIRE(o.error.empty());
  const auto t = makeText(o, 0.3);
  CHECK(t->glyphCount() == 9);
  int checked = 0;
  for (double y : {0.05, 0.1237, 0.25, 0.3333, 0.41, 0.5, 0.62, 0.7}) {
    const std::vector<LD> xs = lineCrossingsX(o, y);
    const Ray ray(Vec3(-1, y, 0.15), Vec3(1, 0, 0));
    CrossingList cl;
    t->crossings(ray, cl);
    INFO("y = " << y);
    CHECK(crossingsViolation(*t, ray, cl).empty());
    CHECK(intersectAgreesWithCrossings(*t, ray).empty());
    REQUIRE(cl.items.size() == xs.size());
    for (size_t k = 0; k < xs.size(); ++k) {
      CHECK(std::fabs(cl.items[k].hit.t - (double)(xs[k] + 1)) <= 1e-12);
      CHECK(cl.items[k].entering == (k % 2 == 0));
      ++checked;
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("text: random rays keep the crossings contract and the inside test agrees",
          "[primitives][text]") {
  const TextOutline o = textOutline(kFont, "8oe AV", Vec2(-0.3, 0.02));  // overlapping glyphs
  const auto t = makeText(o, 0.4);
  Rng rng(7);
  int hits = 0;
  for (int i = 0; i < 4000; ++i) {
    const Ray ray = randomRayAt(rng, t->bounds());
    INFO("ray " << i);
    REQUIRE(intersectAgreesWithCrossings(*t, ray).empty());
    CrossingList cl;
    t->crossings(ray, cl);
    for (size_t k = 0; k + 1 < cl.items.size(); ++k) {
      const double mid = 0.5 * (cl.items[k].hit.t + cl.items[k + 1].hit.t);
      if (cl.items[k + 1].hit.t - cl.items[k].hit.t < 1e-6) continue;
      CHECK(t->inside(ray.at(mid)) == cl.items[k].entering);
    }
    hits += !cl.items.empty();
  }
  CHECK(hits > 500);
}

TEST_CASE("text: damaged, missing and non-font files are errors, never crashes",
          "[primitives][text]") {
  CHECK_FALSE(textOutline("/nonexistent/font.ttf", "a", Vec2(0.0)).error.empty());
  std::ifstream in(kFont, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 100000);
  const auto dir = std::filesystem::temp_directory_path() / "lucent-text-test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "damaged.ttf").string();
  auto write = [&](const std::string& b) { std::ofstream(path, std::ios::binary) << b; };
  write("not a font at all");
  CHECK_FALSE(textOutline(path, "a", Vec2(0.0)).error.empty());
  write(bytes.substr(0, 2000));  // truncated inside the table directory's tables
  CHECK_FALSE(textOutline(path, "a", Vec2(0.0)).error.empty());
  // Mutations: bytes overwritten at random places; the layout either fails with a message
  // or gives outlines the Text accepts (or rejects with invalid_argument).
  Rng rng(11);
  int failed = 0;
  for (int m = 0; m < 60; ++m) {
    std::string b = bytes;
    for (int k = 0; k < 20; ++k)
      b[static_cast<size_t>(uniform(rng, 0, b.size() - 1))] =
          static_cast<char>(uniform(rng, 0, 256));
    if (m % 3 == 0) b.resize(static_cast<size_t>(uniform(rng, 12, b.size())));
    write(b);
    const TextOutline o = textOutline(path, "Lucent 8oe", Vec2(0.0));
    if (!o.error.empty()) {
      ++failed;
      continue;
    }
    try {
      const auto t = makeText(o, 1.0);
      CHECK((t->bounds().empty() || t->bounds().isBounded()));
      Hit h;
      t->intersect(Ray(Vec3(-1, 0.3, 0.5), Vec3(1, 0, 0)), h);  // answers, does not hang
    } catch (const std::invalid_argument&) {
      ++failed;
    }
  }
  INFO(failed << " of 60 mutations refused");
  std::filesystem::remove_all(dir);
}

TEST_CASE("text: a box minus an inverse text is the box and the text intersected",
          "[primitives][text][csg]") {
  auto world = [](const std::string& body) {
    ParseResult p =
        parseSceneString("<scene version=\"1\"><camera/>" + body + "</scene>", "text.xml");
    std::string all;
    for (const Diagnostic& d : p.diagnostics.all()) all += d.str() + "\n";
    INFO(all);
    REQUIRE(p.scene);
    REQUIRE(p.diagnostics.errorCount() == 0);
    return std::make_unique<World>(*p.scene);
  };
  const std::string box = R"(<box min="0.1 0.1 0.1" max="1.2 0.6 0.4"/>)";
  const std::string text = R"(<text string="o8" thickness="0.5")";
  auto a = world("<difference>" + box + text + R"( inverse="true"/></difference>)");
  auto b = world("<intersection>" + box + text + "/></intersection>");
  auto c = world("<difference>" + box + text + "/></difference>");
  int hits = 0, differ = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) {
      const Ray ray(Vec3(0.05 + 1.2 * i / 40, 0.05 + 0.6 * j / 20, -1),
                    glm::normalize(Vec3(0.1, 0.05, 1)));
      Hit ha, hb, hc;
      const bool fa = a->intersect(ray, ha), fb = b->intersect(ray, hb), fc = c->intersect(ray, hc);
      REQUIRE(fa == fb);
      if (fa) {
        ++hits;
        CHECK(ha.t == Approx(hb.t).margin(1e-12));
      }
      differ += fa != fc || (fa && std::fabs(ha.t - hc.t) > 1e-9);
    }
  CHECK(hits > 100);
  CHECK(differ > 100);  // the inverse changes what is cut
}

TEST_CASE("text: an empty string or only spaces is an empty shape with a warning",
          "[primitives][text]") {
  for (const char* s : {"", "   "}) {
    ParseResult p = parseSceneString(
        std::string("<scene version=\"1\"><camera/><text string=\"") + s + "\"/></scene>",
        "text.xml");
    REQUIRE(p.scene);
    CHECK(p.diagnostics.errorCount() == 0);
    std::string all;
    for (const Diagnostic& d : p.diagnostics.all()) all += d.str() + "\n";
    CHECK(all.find("warning: <text>: the string has no visible glyph") != std::string::npos);
    World w(*p.scene);
    Hit h;
    CHECK_FALSE(w.intersect(Ray(Vec3(0.3, 0.3, -1), Vec3(0, 0, 1)), h));
  }
}
