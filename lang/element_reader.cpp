#include "element_reader.h"
#include "povray_names.h"

#include "transform_syntax.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_set>

namespace lucent {

namespace {
std::string quote(std::string_view s) { return "'" + std::string(trim(s)) + "'"; }
}  // namespace

ElementReader::ElementReader(ParseContext& ctx, const SourceFile& file, pugi::xml_node element)
    : ctx_(ctx), file_(file), el_(element) {}

SourceLoc ElementReader::valueLoc(const char* attr) const {
  pugi::xml_attribute a = el_.attribute(attr);
  return a ? file_.valueLoc(a, el_) : loc();
}

void ElementReader::attrError(const char* attr, const std::string& message) {
  ctx_.diags.error(valueLoc(attr), tag() + " attribute '" + attr + "': " + message +
                                       instanceNote(ctx_.scope.get()));
  failed_ = true;
}

void ElementReader::error(const std::string& message) {
  ctx_.diags.error(loc(), message + instanceNote(ctx_.scope.get()));
  failed_ = true;
}

void ElementReader::warning(const std::string& message) { ctx_.diags.warning(loc(), message); }

void ElementReader::checkAttributes(const std::vector<std::string_view>& allowed,
                                    const std::function<std::string(std::string_view)>& explain) {
  // Elements have a handful of attributes: a linear scan beats hashing here.
  for (pugi::xml_attribute a = el_.first_attribute(); a; a = a.next_attribute()) {
    std::string_view n = a.name();
    bool known = std::find(allowed.begin(), allowed.end(), n) != allowed.end();
    if (!known) {
      std::string specific = explain ? explain(n) : std::string();
      std::string pov = specific.empty() ? povrayAttributeHint(el_.name(), n) : std::string();
      ctx_.diags.error(file_.nameLoc(a, el_),
                       specific.empty()
                           ? tag() + ": unknown attribute '" + std::string(n) + "'" +
                                 (pov.empty() ? didYouMean(n, allowed) : pov)
                           : tag() + " attribute '" + std::string(n) + "': " + specific);
      failed_ = true;
      continue;
    }
    for (pugi::xml_attribute b = el_.first_attribute(); b != a; b = b.next_attribute())
      if (n == b.name()) {
        ctx_.diags.error(file_.nameLoc(a, el_), tag() + ": attribute '" + std::string(n) +
                                                    "' is given twice (first at " +
                                                    file_.nameLoc(b, el_).str() + ")");
        failed_ = true;
        break;
      }
  }
}

std::optional<std::string> ElementReader::text(const char* attr) {
  pugi::xml_attribute a = el_.attribute(attr);
  if (!a) return std::nullopt;
  SubstitutionError error;
  std::optional<std::string> v = ctx_.params.substitute(a.value(), ctx_.scope.get(), error);
  if (!v) {
    if (!error.message.empty()) {
      SourceLoc where = error.offset != std::string::npos ? file_.locInValue(a, el_, error.offset)
                                                          : valueLoc(attr);
      ctx_.diags.error(where, tag() + " attribute '" + attr + "': " + error.message +
                                  instanceNote(ctx_.scope.get()));
    }
    failed_ = true;
  }
  return v;
}

std::optional<FunctionText> ElementReader::function(
    const char* attr, const std::vector<std::string>& variables,
    const std::vector<std::shared_ptr<const PigmentFunction>>& pigments) {
  pugi::xml_attribute a = el_.attribute(attr);
  if (!a) return std::nullopt;
  // Written with ${...}: substituted first, and an error then points at the value.
  const bool substituted = std::strchr(a.value(), '$') != nullptr;
  std::string value = a.value();
  if (substituted) {
    auto t = text(attr);
    if (!t) return std::nullopt;
    value = *t;
  }
  SubstitutionError error;
  std::optional<FunctionText> f =
      ctx_.params.function(value, ctx_.scope.get(), variables, error, pigments);
  if (!f) {
    if (!error.message.empty()) {
      SourceLoc where = !substituted && error.offset != std::string::npos
                            ? file_.locInValue(a, el_, error.offset)
                            : valueLoc(attr);
      ctx_.diags.error(where, tag() + " attribute '" + attr + "': " + error.message +
                                  instanceNote(ctx_.scope.get()));
    }
    failed_ = true;
  }
  return f;
}

std::optional<double> ElementReader::optionalNumber(const char* attr, const NumberRule& rule) {
  // Expression-valued numbers skip the text round trip (the value is the same).
  if (pugi::xml_attribute a = el_.attribute(attr); a && std::strchr(a.value(), '$')) {
    double v;
    if (ctx_.params.evaluateNumbers(a.value(), ctx_.scope.get(), &v, 1) && rule.accepts(v))
      return v;
  }
  auto t = text(attr);
  if (!t) return std::nullopt;
  Parsed<double> n = parseNumber(*t, rule.allowInfinity);
  if (!n) {
    attrError(attr, n.error);
    return std::nullopt;
  }
  if (!rule.accepts(*n)) {
    attrError(attr, std::string("expected ") + rule.expected + ", got " + quote(*t));
    return std::nullopt;
  }
  return *n;
}

double ElementReader::number(const char* attr, double def, const NumberRule& rule) {
  return optionalNumber(attr, rule).value_or(def);
}

long long ElementReader::integer(const char* attr, long long def, long long min, long long max) {
  auto t = text(attr);
  if (!t) return def;
  Parsed<long long> n = parseInteger(*t);
  if (!n) {
    attrError(attr, n.error);
    return def;
  }
  if (*n < min || *n > max) {
    std::string expected = max >= kNoIntegerLimit ? "a whole number >= " + std::to_string(min)
                                                  : "a whole number from " + std::to_string(min) +
                                                        " to " + std::to_string(max);
    attrError(attr, "expected " + expected + ", got " + quote(*t));
    return def;
  }
  return *n;
}

Vec3 ElementReader::vector(const char* attr, const Vec3& def) {
  if (pugi::xml_attribute a = el_.attribute(attr); a && std::strchr(a.value(), '$')) {
    double v[3];
    if (ctx_.params.evaluateNumbers(a.value(), ctx_.scope.get(), v, 3))
      return Vec3(v[0], v[1], v[2]);
  }
  auto t = text(attr);
  if (!t) return def;
  Parsed<Vec3> v = parseVector(*t);
  if (!v) {
    attrError(attr, v.error);
    return def;
  }
  return *v;
}

Vec3 ElementReader::direction(const char* attr, const Vec3& def) {
  if (!has(attr)) return def;
  bool before = failed_;
  Vec3 v = vector(attr, def);
  if (failed_ && !before) return def;
  double len = glm::length(v);
  if (!(len > 0.0) || !std::isfinite(len)) {
    attrError(attr, "a direction must not be the zero vector, got " + quote(verbatim(attr)));
    return def;
  }
  return v / len;
}

Color ElementReader::color(const char* attr, const Color& def, bool* scalar, bool allowNegative) {
  auto t = text(attr);
  if (!t) return def;
  Parsed<ParsedColor> c = parseColor(*t);
  if (!c) {
    attrError(attr, c.error);
    return def;
  }
  const Color& v = c->color;
  if (!allowNegative && (v.r < 0.0f || v.g < 0.0f || v.b < 0.0f)) {
    attrError(attr, "colour components must not be negative, got " + quote(*t));
    return def;
  }
  if (scalar) *scalar = c->scalar;
  return v;
}

bool ElementReader::boolean(const char* attr, bool def) {
  auto t = text(attr);
  if (!t) return def;
  Parsed<bool> b = parseBool(*t);
  if (!b) {
    attrError(attr, b.error);
    return def;
  }
  return *b;
}

Mat4 ElementReader::transform(const char* attr) {
  pugi::xml_attribute a = el_.attribute(attr);
  if (!a) return Mat4(1.0);
  auto t = text(attr);
  if (!t) return Mat4(1.0);
  TransformSyntaxResult r = parseTransformSyntax(*t);
  if (r.ok) return r.matrix;
  std::string message = r.error;
  if (!r.unknownOperation.empty())
    message += didYouMean(r.unknownOperation, transformOperationNames());
  // Point into the value when it was written without parameters (offsets then match).
  // The position comes from the text as read: pugixml turned the value's newlines into
  // spaces in place, but the file's line starts were taken before.
  SourceLoc where = valueLoc(attr);
  std::string_view v = a.value();
  if (*t == v && r.errorOffset < v.size())
    if (auto inside = file_.locOf(a.value() + r.errorOffset)) where = *inside;
  ctx_.diags.error(
      where, tag() + " attribute '" + attr + "': " + message + instanceNote(ctx_.scope.get()));
  failed_ = true;
  return Mat4(1.0);
}

void ElementReader::forEachChild(const std::function<void(pugi::xml_node)>& f) {
  for (pugi::xml_node c = el_.first_child(); c; c = c.next_sibling()) {
    if (c.type() == pugi::node_element) {
      f(c);
    } else if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
      const char* value = c.value();
      size_t skip = 0;
      while (value[skip] == ' ' || value[skip] == '\t' || value[skip] == '\n' ||
             value[skip] == '\r')
        ++skip;
      std::string_view v = trim(value);
      if (v.empty()) continue;
      std::string shown(v.substr(0, 24));
      if (v.size() > 24) shown += "...";
      ctx_.diags.error(file_.locOf(value + skip).value_or(loc()),
                       tag() + " contains text '" + shown + "'; values go into attributes");
      failed_ = true;
    }
  }
}

std::string elementList(const std::vector<std::string_view>& names) {
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
    list +=
        (i ? (i + 1 == names.size() ? " or " : ", ") : "") + ("<" + std::string(names[i]) + ">");
  return list;
}

}  // namespace lucent
