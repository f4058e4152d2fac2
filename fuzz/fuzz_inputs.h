// What each fuzz target does with one input, shared by the libFuzzer entry points
// (fuzz/*_fuzz.cpp, built with -DLUCENT_FUZZ=ON) and the regression test that replays the
// kept inputs through the normal build (tests/fuzz/fuzz_regression_test.cpp).
//
// Each function returns the outcome: accepted, refused in an orderly way, or a finding (a
// broken promise, with what broke). The entry points abort on a finding so that libFuzzer
// keeps the input; the regression test checks the outcome. Sanitizer reports, signals, hangs
// and runaway memory are findings too, caught by the sanitizers and libFuzzer themselves.
// Orderly refusals are the located diagnostics of the parser and the exceptions the command
// line turns into exit status 2 or 3 (see refusedInOrder).
#pragma once

#include "fuzz/expansion_scene.h"
#include "images/height_map_file.h"
#include "lang/expression.h"
#include "lang/parser.h"
#include "lang/transform_syntax.h"
#include "meshes/mesh_files.h"
#include "primitives/height_field.h"
#include "primitives/text.h"
#include "primitives/text_outline.h"
#include "primitives/transform.h"
#include "render/camera_frame.h"
#include "render/image_read.h"
#include "render/renderer.h"
#include "render/texture.h"
#include "scenegraph/located_error.h"
#include "scenegraph/world.h"
#include "sdl/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lucent::fuzz {

struct Outcome {
  bool accepted = false;  // parsed (and built), or read
  std::string finding;    // empty unless a promise was broken
};

inline Outcome accepted() { return {true, {}}; }
inline Outcome refused() { return {false, {}}; }
inline Outcome finding(std::string what) { return {false, std::move(what)}; }

// What may escape from building the world and tracing a pixel without being a bug: the
// errors `lucent render` reports as an invalid scene (exit status 2) or a failure to read a
// file (3). World reports a singular or overflowing nested transform as a std::runtime_error
// whose message starts with the node's location, "FILE:LINE:COL: error: ", so any exception
// whose message is located counts as such a report. A located error type for the errors
// found after parsing, once there is one, belongs in the list of types below.
inline bool locatedMessage(std::string_view m) {
  size_t i = m.find(": error: ");
  if (i == std::string_view::npos) return false;
  for (int field = 0; field < 2; ++field) {  // ":COL", then ":LINE", right before it
    const size_t end = i;
    while (i > 0 && m[i - 1] >= '0' && m[i - 1] <= '9') --i;
    if (i == end || i == 0 || m[i - 1] != ':') return false;
    --i;
  }
  return i > 0;  // and a file name before them
}

inline bool refusedInOrder(const std::exception& e) {
  if (dynamic_cast<const LocatedError*>(&e) || dynamic_cast<const ImageIOError*>(&e) ||
      dynamic_cast<const MeshError*>(&e))
    return true;
  return locatedMessage(e.what());
}

// A valid scene built and one pixel traced through each camera, as `lucent render` would,
// with the settings that only make a render slow kept small.
inline Outcome builtAndTraced(Scene& scene) {
  scene.render.samples = std::min(scene.render.samples, 2);
  scene.render.maxDepth = std::min(scene.render.maxDepth, 8);
  for (Light& light : scene.lights) {
    light.samplesU = std::min(light.samplesU, 4);
    light.samplesV = std::min(light.samplesV, 4);
  }
  try {
    World world(scene);
    for (const Camera& camera : scene.cameras) {
      Renderer renderer(world, camera);
      TraceContext context;
      renderer.renderPixel(scene.render.width / 2, scene.render.height / 2, context);
    }
  } catch (const std::exception& e) {
    if (refusedInOrder(e)) return refused();
    return finding(std::string("an exception escaped that is not a located refusal: ") + e.what());
  }
  return accepted();
}

// The scene is parsed as if it were a file in examples/, so its includes and meshes can
// reach real files (examples/parts, examples/meshes) and nothing outside that folder.
inline Outcome sceneParser(const uint8_t* data, size_t size, const std::string& virtualPath) {
  std::string xml(reinterpret_cast<const char*>(data), size);
  ParseResult parsed = parseSceneString(xml, virtualPath);
  // The parser turns an escaped exception into an "internal error" diagnostic rather than
  // crash; for the fuzzer that is still a bug to find. Only a message that starts so: a
  // scene's own text can contain the words (tests/fuzz/crashes/scene_parser/).
  for (const Diagnostic& d : parsed.diagnostics.all())
    if (d.message.rfind("internal error while reading the scene", 0) == 0) return finding(d.str());
  if (!parsed.scene) {
    if (!parsed.diagnostics.hasErrors()) return finding("no scene and no error");
    return refused();
  }
  return builtAndTraced(*parsed.scene);
}

// The POV-Ray importer (sdl/): the text read as a scene file lying in tests/data/sdl/samples
// (whose includes it may read, with the standard include folder), evaluated within limits
// small enough for a fuzzer's pace, then built and traced as above. Every error must be
// located; an "internal error" diagnostic is an exception that escaped, a finding.
inline Outcome povImporter(const uint8_t* data, size_t size, const std::string& folder) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sdl::CollectedOutput out;
  sdl::Options options;
  options.output = &out;
  options.imageWidth = 32;
  options.imageHeight = 24;
  options.limits.tokens = 2'000'000;
  options.limits.loopIterations = 20'000;
  options.limits.stringLength = 1 << 16;
  options.limits.arrayElements = 1 << 16;
  sdl::SceneLoad load = sdl::loadSceneText("fuzz.pov", text, folder, options);
  for (const Diagnostic& d : load.diagnostics.all()) {
    if (d.message.rfind("internal error while reading the scene", 0) == 0) return finding(d.str());
    if (d.severity == Severity::Error && d.loc.file.empty())
      return finding("an error without a place: " + d.message);
  }
  if (!load.scene) {
    if (!load.diagnostics.hasErrors()) return finding("no scene and no error");
    return refused();
  }
  return builtAndTraced(*load.scene);
}

// The result keeps its promises: an accepted transform is finite and invertible (the scene
// builds an Instance from it), a refused one says why at an offset inside the text.
inline Outcome transformSyntax(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  TransformSyntaxResult r = parseTransformSyntax(text);
  if (!r.ok) {
    if (r.error.empty()) return finding("refused without a message");
    if (r.errorOffset > text.size()) return finding("error offset outside the text: " + r.error);
    return refused();
  }
  if (!r.error.empty()) return finding("accepted with a message: " + r.error);
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(r.matrix[c][row])) return finding("accepted a matrix that is not finite");
  if (!Transform::fromMatrix(r.matrix)) return finding("accepted a matrix that cannot be inverted");
  return accepted();
}

inline Outcome meshReader(const uint8_t* data, size_t size, MeshFormat format) {
  try {
    loadMeshBytes(std::string(reinterpret_cast<const char*>(data), size), format);
  } catch (const MeshError&) {
    return refused();
  }
  return accepted();
}

// A font file's bytes: laid out by FreeType as <text> lays out a string with holes, kerning
// pairs and a space, built into the Text shape and crossed by a fan of rays. A message from
// the layout or a Text that refuses the outlines is a refusal; the crossings must keep the
// contract (sorted, alternating from outside: the rays start left of the text's bounds,
// wherever a damaged font put its outlines).
inline Outcome fontReader(const uint8_t* data, size_t size) {
  const TextOutline o = textOutlineFromBytes(std::string(reinterpret_cast<const char*>(data), size),
                                             "Lo8e AV", Vec2(0.0));
  if (!o.error.empty()) return refused();
  std::vector<std::vector<PrismContour>> glyphs;
  for (const PlacedGlyph& g : o.glyphs) glyphs.push_back(g.contours);
  std::optional<Text> text;
  try {
    text.emplace(glyphs, 0.5);
  } catch (const std::invalid_argument&) {
    return refused();
  }
  const AABB box = text->bounds();
  if (box.empty()) return accepted();
  const double startX = box.lo.x - 10.0;
  for (int i = 0; i < 16; ++i) {
    const Ray ray(Vec3(startX, 0.05 * i, 0.25), Vec3(1, 0.001 * i, 0.0));
    CrossingList cl;
    text->crossings(ray, cl);
    bool in = cl.startsInside;
    if (in) return finding("a ray from far outside starts inside the text");
    double last = -kInf;
    for (const Crossing& c : cl.items) {
      if (!(c.hit.t >= last)) return finding("text crossings not sorted");
      if (c.entering == in) return finding("text crossings do not alternate");
      in = c.entering;
      last = c.hit.t;
    }
  }
  return accepted();
}

// A height field's image file (written to a temporary file, since the reader takes a
// path: OpenImageIO's formats, POV-Ray's reading of them), built into a HeightField and
// crossed by a fan of rays. A HeightMapError is a refusal; the crossings must keep the
// contract (sorted, alternating from outside: the rays start far outside the field).
inline Outcome heightMapReader(const uint8_t* data, size_t size) {
  char path[] = "/tmp/lucent-fuzz-height-XXXXXX.png";
  const int fd = mkstemps(path, 4);
  if (fd < 0) return refused();
  FILE* f = fdopen(fd, "wb");
  if (!f) return refused();
  const bool written = fwrite(data, 1, size, f) == size;
  fclose(f);
  std::shared_ptr<const HeightMap> map;
  try {
    if (written) map = readHeightMapFile(path);
  } catch (const HeightMapError&) {
  }
  std::remove(path);
  if (!map) return refused();
  // An image with nothing above the water level (all black) is refused by the scene parser
  // with a located error before a HeightField is built, so the harness refuses it too.
  if (*std::max_element(map->values.begin(), map->values.end()) == 0) return refused();
  for (bool smooth : {false, true}) {
    const HeightField field(map, smooth, 0.0);
    for (int i = 0; i < 16; ++i) {
      const Ray ray(Vec3(-10, 0.06 * i, 0.03 + 0.06 * i), Vec3(1, 0.001 * (i - 8), 0.01 * i));
      CrossingList cl;
      field.crossings(ray, cl);
      bool in = cl.startsInside;
      if (in) return finding("a ray from far outside starts inside the height field");
      double last = -kInf;
      for (const Crossing& c : cl.items) {
        if (!(c.hit.t >= last)) return finding("height field crossings not sorted");
        if (c.entering == in) return finding("height field crossings do not alternate");
        in = c.entering;
        last = c.hit.t;
      }
      if (in) return finding("a ray ends inside the height field");
    }
  }
  return accepted();
}

// The names the expression target's evaluator knows: numbers (ordinary, huge, tiny, zero),
// a parameter that is not one number, and one whose problem was already reported.
class ExpressionFuzzNames final : public ExpressionNames {
 public:
  std::optional<double> number(std::string_view name, std::string& error, bool& known) override {
    known = true;
    for (const auto& [n, v] : kNumbers)
      if (name == n) return v;
    if (name == "text") {
      error = "the parameter 'text' is 'a b', not one number";
      return std::nullopt;
    }
    if (name == "reported") return std::nullopt;  // empty error: said already
    known = false;
    return std::nullopt;
  }
  std::vector<std::string> visibleNames() override {
    std::vector<std::string> names{"text", "reported"};
    for (const auto& [n, v] : kNumbers) names.emplace_back(n);
    return names;
  }

 private:
  static constexpr std::pair<const char*, double> kNumbers[] = {{"i", 3},
                                                                {"r", 0.5},
                                                                {"n", 10},
                                                                {"zero", 0},
                                                                {"neg", -2},
                                                                {"big", 1e308},
                                                                {"tiny", 4.9e-324},
                                                                {"pi", 3.141592653589793},
                                                                {"e", 2.718281828459045}};
};

// The expression scene: the input is the text of ${...} in an attribute on its own line, in
// a repeat with a local parameter, beside top-level parameters (one not a number, one that
// refers to itself).
constexpr int kExpressionLine = 6;
inline std::string expressionScene(std::string_view text, size_t& valueColumn,
                                   size_t& valueLength) {
  std::string escaped;
  for (unsigned char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\n':
        escaped += "&#10;";
        break;
      case '\t':
        escaped += "&#9;";
        break;
      case '\r':
        escaped += "&#13;";
        break;
      default:
        escaped += c < 0x20 ? ' ' : static_cast<char>(c);  // not allowed in XML even escaped
    }
  }
  const std::string before = "<sphere radius=\"";
  valueColumn = before.size() + 1;
  valueLength = escaped.size() + 3;  // with ${ and }
  return "<scene version=\"1\">\n"
         "<camera position=\"0 0 5\" look-at=\"0 0 0\"/>\n"
         "<param name=\"r\" value=\"2\"/><param name=\"s\" value=\"1 2 3\"/><param name=\"c\" "
         "value=\"${c+1}\"/>\n"
         "<repeat var=\"i\" count=\"2\">\n"
         "<param name=\"k\" value=\"${i*2}\"/>\n" +
         before + "${" + escaped + "}\"/>\n" +
         "</repeat>\n"
         "</scene>\n";
}

// Arbitrary text as an expression: evaluated directly (the result is finite; an error has a
// message and an offset inside the text; a second evaluation, from the cache, agrees), then
// inside a scene, where every error must point into the attribute that holds it (or at the
// parameters it used).
inline Outcome expression(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  bool ok = false;
  {
    ExpressionEvaluator evaluator;
    ExpressionFuzzNames names;
    std::optional<double> first;
    std::string firstText;
    for (int round = 0; round < 2; ++round) {
      ExpressionError error;
      std::optional<double> v = evaluator.evaluate(text, names, error);
      if (v && !std::isfinite(*v)) return finding("a result that is not finite");
      if (!v && error.message.empty() && !error.reported)
        return finding("an error without a message");
      if (!v && error.offset >= std::max<size_t>(1, text.size()))
        return finding("error offset " + std::to_string(error.offset) +
                       " outside the text: " + error.message);
      const std::string shown =
          v ? formatNumber(*v) : "error at " + std::to_string(error.offset) + ": " + error.message;
      if (round == 0) {
        first = v;
        firstText = shown;
      } else if (v.has_value() != first.has_value() ||
                 (v && std::memcmp(&*v, &*first, sizeof(double)) != 0)) {
        return finding("a second evaluation of the same text gives another answer: " + firstText +
                       ", then " + shown);
      }
    }
    ok = first.has_value();
  }
  size_t column = 0, length = 0;
  const std::string xml = expressionScene(text, column, length);
  ParseResult parsed =
      parseSceneString(xml, std::string(LUCENT_SOURCE_DIR) + "/examples/fuzz-input.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) {
    if (d.message.rfind("internal error while reading the scene", 0) == 0) return finding(d.str());
    if (d.severity != Severity::Error) continue;
    if (d.loc.line == 3) continue;  // at the parameter the expression used
    if (d.loc.line != kExpressionLine || d.loc.col < static_cast<int>(column) ||
        d.loc.col >= static_cast<int>(column + length))
      return finding("an error outside the expression's attribute: " + d.str());
  }
  if (!parsed.scene && !parsed.diagnostics.hasErrors()) return finding("no scene and no error");
  return ok ? accepted() : refused();
}

// Bytes as a program that writes a scene of repeats, ifs, local parameters and (parameterised)
// uses (fuzz/expansion_scene.h), which is then parsed, built and traced like any scene.
inline Outcome expansion(const uint8_t* data, size_t size) {
  const std::string xml = expansionScene(data, size);
  return sceneParser(reinterpret_cast<const uint8_t*>(xml.data()), xml.size(),
                     std::string(LUCENT_SOURCE_DIR) + "/examples/fuzz-input.xml");
}

// For the libFuzzer entry points: a finding stops the run, and libFuzzer keeps the input.
inline void abortOnFinding(const Outcome& outcome) {
  if (outcome.finding.empty()) return;
  std::fprintf(stderr, "fuzz finding: %s\n", outcome.finding.c_str());
  __builtin_trap();
}

}  // namespace lucent::fuzz
