// <parametric x="..." y="..." z="..." uv-min uv-max container min max center radius
// max-gradient accuracy precompute precompute-coordinates/>: POV-Ray's parametric surface
// (primitives/parametric.h). Each coordinate is an expression of the scene language in u
// and v, compiled where it is read; POV-Ray gets each as a function { } body, whose u and v
// are its own names for the parameters. Not a solid.
#include "container_fields.h"

#include "scenegraph/shape_type.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace lucent {

namespace {

constexpr const char* kCoordinates[] = {"x", "y", "z"};

// The samples' functions, written in C++ (the registry knows no expression compiler).
class SampleField final : public ScalarField {
 public:
  explicit SampleField(double (*f)(double, double)) : f_(f) {}
  double value(const Vec3& p) const override { return f_(p.x, p.y); }

 private:
  double (*f_)(double, double);
};

ParametricSpec sample(std::array<const char*, 3> text, std::array<double (*)(double, double), 3> f,
                      Vec2 lo, Vec2 hi, double maxGradient) {
  auto functions = std::make_shared<ParametricFunctions>();
  for (int i = 0; i < 3; ++i) {
    functions->text[i] = text[i];
    functions->fields[i] = std::make_shared<SampleField>(f[i]);
  }
  ParametricSpec s;
  s.functions = functions;
  s.uvMin = lo;
  s.uvMax = hi;
  s.container.min = Vec3(-1.5);
  s.container.max = Vec3(1.5);
  s.maxGradient = maxGradient;
  return s;
}

std::optional<Vec2> pair(AttributeInput& in, const char* attr, Vec2 def) {
  if (!in.has(attr)) return def;
  auto list = in.numbers(attr);
  if (!list) return std::nullopt;
  if (list->size() != 2) {
    in.attrError(attr, fmt::format("expected two numbers (u v), got {}", list->size()));
    return std::nullopt;
  }
  return Vec2((*list)[0], (*list)[1]);
}

// "x y z" or any of them, each once.
std::optional<std::array<bool, 3>> coordinates(AttributeInput& in) {
  std::array<bool, 3> out{true, true, true};
  if (!in.has("precompute-coordinates")) return out;
  auto text = in.text("precompute-coordinates");
  if (!text) return std::nullopt;
  out = {false, false, false};
  std::istringstream words(*text);
  std::string w;
  while (words >> w) {
    int i = w == "x" ? 0 : w == "y" ? 1 : w == "z" ? 2 : -1;
    if (i < 0 || out[i]) {
      in.attrError("precompute-coordinates", i < 0 ? "'" + w + "' is not a coordinate (x, y or z)"
                                                   : "'" + w + "' is given twice");
      return std::nullopt;
    }
    out[i] = true;
  }
  return out;
}

void readParametric(ParametricSpec& s, AttributeInput& in) {
  auto functions = std::make_shared<ParametricFunctions>();
  bool complete = true;
  for (int i = 0; i < 3; ++i) {
    const char* a = kCoordinates[i];
    if (auto f = in.function(a, {"u", "v"})) {
      functions->text[i] = f->text;
      functions->constants[i] = f->constants;
      functions->fields[i] = f->field;
    } else {
      complete = false;
      if (!in.has(a))
        in.error(std::string("<parametric> needs '") + a + "' (an expression in u and v)");
    }
  }
  if (complete) s.functions = functions;
  const auto lo = pair(in, "uv-min", Vec2(0.0)), hi = pair(in, "uv-max", Vec2(1.0));
  if (lo && hi) {
    s.uvMin = *lo;
    s.uvMax = *hi;
    if (!(lo->x < hi->x && lo->y < hi->y))
      in.attrError(in.has("uv-max") ? "uv-max" : "uv-min",
                   fmt::format("the (u, v) rectangle needs uv-min < uv-max in u and in v (uv-min "
                               "{} {}, uv-max {} {})",
                               lo->x, lo->y, hi->x, hi->y));
  }
  s.container = readContainer(in);
  s.precomputeDepth =
      static_cast<int>(in.integer("precompute", s.precomputeDepth, 0, Parametric::kMaxPrecompute));
  if (auto c = coordinates(in)) s.precompute = *c;
  if (in.failed() || !complete) return;
  // The table once, when read: every copy of the element shares it.
  std::string problem;
  if (!shareParametricIntervals(s, problem)) in.attrError("precompute", problem);
}

void writeParametric(const ParametricSpec& s, PovShapeOut& out) {
  std::string bodies[3];
  for (int i = 0; i < 3; ++i) {
    std::string problem;
    std::optional<std::string> body =
        out.function(s.functions->text[i], s.functions->constants[i], {}, problem);
    if (!body) {
      out.error(std::string("<parametric> ") + kCoordinates[i] + ": " + problem);
      return;
    }
    bodies[i] = *body;
  }
  out.open("parametric");
  for (const std::string& b : bodies) out.line("function { " + b + " }");
  out.line(fmt::format("<{}, {}>, <{}, {}>", out.number(s.uvMin.x), out.number(s.uvMin.y),
                       out.number(s.uvMax.x), out.number(s.uvMax.y)));
  out.line(povContainer(s.container, out));
  out.line("max_gradient " + out.number(s.maxGradient));
  out.line("accuracy " + out.number(s.accuracy));
  if (s.precomputeDepth > 0 && (s.precompute[0] || s.precompute[1] || s.precompute[2])) {
    std::string which;
    for (int i = 0; i < 3; ++i)
      if (s.precompute[i]) which += std::string(", ") + kCoordinates[i];
    out.line(fmt::format("precompute {}{}", s.precomputeDepth, which));
  }
}

}  // namespace

bool shareParametricIntervals(ParametricSpec& s, std::string& problem) {
  const int axes = int(s.precompute[0]) + int(s.precompute[1]) + int(s.precompute[2]);
  s.intervals = nullptr;
  if (s.precomputeDepth <= 0 || axes == 0) return true;
  // What makes the table: not the container nor the accuracy.
  std::string key = fmt::format("{} {} {} {} {} {} {} {} {}", s.uvMin.x, s.uvMin.y, s.uvMax.x,
                                s.uvMax.y, s.maxGradient, s.precomputeDepth, s.precompute[0],
                                s.precompute[1], s.precompute[2]);
  for (int i = 0; i < 3; ++i) {
    key += "\n" + s.functions->text[i];
    for (const auto& [name, value] : s.functions->constants[i])
      key += fmt::format(" {}={}", name, value);
  }
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const ParametricIntervals>> tables;
  std::lock_guard<std::mutex> lock(mutex);
  size_t alive = 0;
  for (auto it = tables.begin(); it != tables.end();) {
    if (auto t = it->second.lock()) {
      if (it->first == key) {
        s.intervals = t;
        return true;
      }
      for (int i = 0; i < 3; ++i) alive += t->low[i].size() * 2 * sizeof(double);
      ++it;
    } else {
      it = tables.erase(it);
    }
  }
  const size_t bytes = (size_t(1) << s.precomputeDepth) * 2 * sizeof(double) * size_t(axes);
  if (alive + bytes > kMaxParametricTableBytes) {
    problem = fmt::format(
        "the precomputed bounds of this parametric ({} MB) and of those already read ({} MB) "
        "would pass Lucent's limit of {} MB: lower 'precompute'",
        bytes >> 20, alive >> 20, kMaxParametricTableBytes >> 20);
    return false;
  }
  s.intervals = precomputeParametric(parametricParams(s));
  tables[key] = s.intervals;
  return true;
}

Parametric::Params parametricParams(const ParametricSpec& s) {
  Parametric::Params p;
  if (s.functions) p.functions = s.functions->fields;
  p.uvMin = s.uvMin;
  p.uvMax = s.uvMax;
  p.container = s.container;
  p.maxGradient = s.maxGradient;
  p.accuracy = s.accuracy;
  p.precomputeDepth = s.precomputeDepth;
  p.precompute = s.precompute;
  p.intervals = s.intervals;
  return p;
}

template <>
ShapeEntry<ParametricSpec> shapeEntry<ParametricSpec>() {
  ShapeEntry<ParametricSpec> e(
      "parametric", "parametric surfaces",
      [](const ParametricSpec& s) { return std::make_shared<Parametric>(parametricParams(s)); },
      writeParametric);
  e.doc =
      "POV-Ray's parametric surface: the points (x(u, v), y(u, v), z(u, v)) for (u, v) in a "
      "rectangle, sought within a box or sphere container (not a solid).";
  std::vector<Field<ParametricSpec>> fields;
  for (const char* a : kCoordinates) {
    Field<ParametricSpec> f = readByEntry<ParametricSpec>(a, AttrType::Text);
    f.info.required = true;
    fields.push_back(std::move(f).doc(
        "The point's coordinate as an expression in u and v (the syntax of ${...} expressions, "
        "without ${}); other names are parameters, taken as numbers where the element is "
        "read."));
  }
  fields.push_back(readByEntry<ParametricSpec>("uv-min", AttrType::NumberList, "0 0", {}, 2)
                       .doc("The (u, v) rectangle's lowest corner: u v."));
  fields.push_back(readByEntry<ParametricSpec>("uv-max", AttrType::NumberList, "1 1", {}, 2)
                       .doc("The (u, v) rectangle's highest corner: u v (above uv-min in both)."));
  for (auto& f : containerFields<ParametricSpec>()) fields.push_back(std::move(f));
  fields.push_back(
      numberField("max-gradient", &ParametricSpec::maxGradient, NumberRule::positive())
          .doc("A bound on each coordinate function's slope along u and along v, by which the "
               "search bounds each part of the rectangle."));
  fields.push_back(
      numberField("accuracy", &ParametricSpec::accuracy, NumberRule::positive())
          .doc("The size of the smallest parts the search divides the rectangle into (in u "
               "and v, or in length along the ray)."));
  Field<ParametricSpec> depth = readByEntry<ParametricSpec>("precompute", AttrType::Number, "0");
  depth.info.schemaType = "wholeNumber";
  fields.push_back(std::move(depth).doc(
      "Levels of parts (0 to 20) whose bounds are computed once when the scene is read."));
  fields.push_back(readByEntry<ParametricSpec>("precompute-coordinates", AttrType::Text, "x y z")
                       .doc("The coordinates whose bounds are precomputed: any of x, y, z."));
  e.fields = std::move(fields);
  e.finish = readParametric;
  e.notSolid = [](const ParametricSpec&) {
    return std::string("a parametric surface encloses no volume");
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, ParametricSpec>>{
        {"parametric sphere", sample({"cos(u)*sin(v)", "cos(v)", "sin(u)*sin(v)"},
                                     {[](double u, double v) { return std::cos(u) * std::sin(v); },
                                      [](double, double v) { return std::cos(v); },
                                      [](double u, double v) { return std::sin(u) * std::sin(v); }},
                                     Vec2(0.0), Vec2(2.0 * kPi, kPi), 1.0)},
        {"parametric Moebius strip",
         sample({"cos(u) + v*cos(u/2)*cos(u)", "sin(u) + v*cos(u/2)*sin(u)", "v*sin(u/2)"},
                {[](double u, double v) { return std::cos(u) + v * std::cos(u / 2) * std::cos(u); },
                 [](double u, double v) { return std::sin(u) + v * std::cos(u / 2) * std::sin(u); },
                 [](double u, double v) { return v * std::sin(u / 2); }},
                Vec2(0.0, -0.3), Vec2(2.0 * kPi, 0.3), 1.5)}};
  };
  return e;
}

}  // namespace lucent
