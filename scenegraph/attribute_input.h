// What the tables' readers read attributes through: a shape's entry in the registry
// (shape_type.h), the camera table (camera.h), the light table (light.h) and the finish
// table (finish_terms.h). The scene language implements it over one
// XML element (lang/element_input.h): every getter
// substitutes parameters, parses, checks the range and reports a located error itself, and
// returns the default when the attribute is absent or wrong, so parsing goes on.
#pragma once

#include "primitives/height_map.h"
#include "primitives/math.h"
#include "primitives/mesh_data.h"
#include "primitives/scalar_field.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lucent {

struct PigmentFunction;  // pigment_function.h

// The range a number attribute must lie in, and how the error names it.
struct NumberRule {
  double lo = -kInf, hi = kInf;
  bool loOpen = false, hiOpen = false;
  bool allowInfinity = false;
  const char* expected = "a number";

  static NumberRule any() { return {}; }
  static NumberRule positive() { return {0.0, kInf, true, false, false, "a positive number"}; }
  static NumberRule nonNegative() { return {0.0, kInf, false, false, false, "a number >= 0"}; }
  static NumberRule between(double lo, double hi, const char* expected, bool loOpen = false,
                            bool hiOpen = false) {
    return {lo, hi, loOpen, hiOpen, false, expected};
  }
  bool accepts(double v) const {
    if (v < lo || v > hi) return false;
    if (loOpen && v == lo) return false;
    if (hiOpen && v == hi) return false;
    return true;
  }
};

// A function attribute (an isosurface's), compiled: the field to evaluate, its text and the
// values its names other than the variables stood for where it was read.
struct FunctionInput {
  std::shared_ptr<const ScalarField> field;
  std::string text;
  std::vector<std::pair<std::string, double>> constants;
  std::vector<std::shared_ptr<const PigmentFunction>> pigments{};
};

// An integer attribute's `max` at or above this: no upper bound ("a whole number >= min").
constexpr long long kNoIntegerLimit = 1LL << 40;

class AttributeInput {
 public:
  virtual ~AttributeInput() = default;

  virtual bool has(const char* attr) const = 0;
  virtual double number(const char* attr, double def, const NumberRule& rule) = 0;
  // A whole number from min to max (kNoIntegerLimit: no upper bound).
  virtual long long integer(const char* attr, long long def, long long min, long long max) = 0;
  virtual Vec3 vector(const char* attr, const Vec3& def) = 0;
  // Not zero; returned normalised.
  virtual Vec3 direction(const char* attr, const Vec3& def) = 0;
  virtual bool boolean(const char* attr, bool def) = 0;
  // Three numbers, one for grey, #rrggbb or a CSS name; no negative component. `scalar`,
  // when given, is set to whether it was written as one number, and only when the attribute
  // is read.
  virtual Color color(const char* attr, const Color& def, bool* scalar) = 0;
  Color color(const char* attr, const Color& def) { return color(attr, def, nullptr); }
  // As color, but a component may be negative: where POV-Ray's meaning takes one (a light
  // that darkens, a transmission that subtracts, a surface whose filter and transmit add up
  // to more than 1).
  virtual Color signedColor(const char* attr, const Color& def, bool* scalar) = 0;
  Color signedColor(const char* attr, const Color& def) { return signedColor(attr, def, nullptr); }
  // The index of the value in `names`; `def` when absent or not one of them (reported).
  virtual size_t choice(const char* attr, size_t def,
                        const std::vector<std::string_view>& names) = 0;
  // A transform in the language's syntax (translate(...) scale(...) matrix(...)...); `def`
  // when absent or wrong (reported, located inside the value).
  virtual Mat4 transform(const char* attr, const Mat4& def) = 0;
  // The value after parameter substitution; nullopt when absent or wrong (reported).
  virtual std::optional<std::string> text(const char* attr) = 0;
  // Lists of numbers and of whole numbers >= 0; nullopt when absent or wrong (reported).
  virtual std::optional<std::vector<double>> numbers(const char* attr) = 0;
  virtual std::optional<std::vector<long long>> integers(const char* attr) = 0;
  // A function of `variables` (x, y, z); nullopt when absent or wrong (reported, located
  // inside the expression).
  virtual std::optional<FunctionInput> function(const char* attr,
                                                const std::vector<std::string>& variables) = 0;
  // The mesh file the attribute names, resolved by the scene's file-access rules and read
  // once per process however many elements name it; null when it cannot be read (reported).
  // `firstRead`, if given, tells whether this call read the file.
  virtual std::shared_ptr<const MeshData> meshFile(const char* attr, bool* firstRead = nullptr) = 0;
  // The image the attribute names read as a height field's grid (images/height_map_file.h),
  // resolved by the same rules (its path in `resolved`); null when it cannot be read (reported).
  virtual std::shared_ptr<const HeightMap> heightMapFile(const char* attr,
                                                         std::string& resolved) = 0;

  // The file the attribute names, resolved by the scene's file-access rules (absolute);
  // nullopt when absent or not allowed (reported).
  virtual std::optional<std::string> filePath(const char* attr) = 0;
  // The scene material the attribute names by id (Scene::materials' index); nullopt when
  // absent or unknown (reported).
  virtual std::optional<uint32_t> material(const char* attr) = 0;

  // Each child element named `element` (a shape's own children, which its entry declares,
  // e.g. a blob's <component>), in order, read through an input of its own whose errors
  // are located at the child; the parser reports any other child element itself.
  virtual void forEachChild(const char* element,
                            const std::function<void(AttributeInput&)>& read) = 0;

  // "<sphere> attribute 'radius': message", at the attribute's value.
  virtual void attrError(const char* attr, const std::string& message) = 0;
  // A message about the whole element, at its '<'.
  virtual void error(const std::string& message) = 0;
  virtual void warning(const std::string& message) = 0;
  // Whether any error was reported for this element.
  virtual bool failed() const = 0;
};

}  // namespace lucent
