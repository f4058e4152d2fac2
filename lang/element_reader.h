// Reads one element's attributes strictly: unknown or repeated attributes are errors with
// a did-you-mean hint; each typed getter substitutes parameters, parses, checks the range
// and reports problems as "<element> attribute 'name': ..." at the attribute's value.
// A getter returns the default when the attribute is absent or wrong, so parsing goes on
// and reports every error of the file.
#pragma once

#include "did_you_mean.h"
#include "parse_context.h"
#include "values.h"

#include "scenegraph/attribute_input.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lucent {

class ElementReader {
 public:
  ElementReader(ParseContext& ctx, const SourceFile& file, pugi::xml_node element);

  pugi::xml_node element() const { return el_; }
  const SourceFile& file() const { return file_; }
  ParseContext& ctx() const { return ctx_; }
  std::string name() const { return el_.name(); }
  std::string tag() const { return "<" + name() + ">"; }  // "<sphere>"
  SourceLoc loc() const { return file_.loc(el_); }
  SourceLoc valueLoc(const char* attr) const;

  // Reports every attribute not in `allowed` and every attribute written twice. `explain`
  // may return a specific message for a name that is known elsewhere (an attribute of
  // another camera type, say); "" falls back to "unknown attribute" with did-you-mean.
  void checkAttributes(const std::vector<std::string_view>& allowed,
                       const std::function<std::string(std::string_view)>& explain = {});

  bool has(const char* attr) const { return static_cast<bool>(el_.attribute(attr)); }
  // The value after parameter substitution; nullopt when absent or wrong (reported).
  std::optional<std::string> text(const char* attr);
  // The value as written (no parameter substitution).
  std::string verbatim(const char* attr) const { return el_.attribute(attr).value(); }

  // A function expression of `variables` (an isosurface's), checked and its other names
  // resolved; errors point inside the expression when it was written without ${...}.
  // `pigments`: the pigment functions it may call.
  std::optional<FunctionText> function(
      const char* attr, const std::vector<std::string>& variables,
      const std::vector<std::shared_ptr<const PigmentFunction>>& pigments = {});

  double number(const char* attr, double def, const NumberRule& rule = NumberRule::any());
  std::optional<double> optionalNumber(const char* attr,
                                       const NumberRule& rule = NumberRule::any());
  long long integer(const char* attr, long long def, long long min,
                    long long max = kNoIntegerLimit);
  Vec3 vector(const char* attr, const Vec3& def);
  // A direction: not zero, returned normalised.
  Vec3 direction(const char* attr, const Vec3& def);
  // Non-negative components. `scalar` tells whether it was written as one number.
  // `allowNegative`: a component may be below 0 (AttributeInput::signedColor).
  Color color(const char* attr, const Color& def, bool* scalar = nullptr,
              bool allowNegative = false);
  bool boolean(const char* attr, bool def);
  // A transform attribute (lang/transform_syntax.h); identity if absent.
  Mat4 transform(const char* attr);

  template <class E>
  E choice(const char* attr, E def, const std::vector<std::pair<std::string_view, E>>& table) {
    auto t = text(attr);
    if (!t) return def;
    std::string_view v = trim(*t);
    std::vector<std::string_view> names;
    for (const auto& [n, e] : table) {
      if (n == v) return e;
      names.push_back(n);
    }
    std::string list;
    for (size_t i = 0; i < names.size(); ++i)
      list += (i ? (i + 1 == names.size() ? " or " : ", ") : "") + std::string(names[i]);
    attrError(attr, "expected " + list + ", got '" + std::string(v) + "'" + didYouMean(v, names));
    return def;
  }

  // "<sphere> attribute 'radius': message", at the attribute's value.
  void attrError(const char* attr, const std::string& message);
  // A message about the whole element, at its '<'.
  void error(const std::string& message);
  void warning(const std::string& message);
  bool failed() const { return failed_; }
  // For an error reported on a child element that makes this element unusable too.
  void markFailed() { failed_ = true; }

  // Calls `f` for every child element; text other than whitespace is an error.
  void forEachChild(const std::function<void(pugi::xml_node)>& f);

 private:
  ParseContext& ctx_;
  const SourceFile& file_;
  pugi::xml_node el_;
  bool failed_ = false;
};

// "a, b or c" with the names quoted as elements: "<sphere>, <box> or <group>".
std::string elementList(const std::vector<std::string_view>& names);

}  // namespace lucent
