// The AttributeInput (scenegraph/attribute_input.h) of one XML element: what the shape
// registry's entries and the finish table's rows read their attributes through. Every getter
// goes through the element's ElementReader (parameters, parsing, ranges, located errors).
#pragma once

#include "element_reader.h"

#include "scenegraph/attribute_input.h"

namespace lucent {

class ElementInput final : public AttributeInput {
 public:
  explicit ElementInput(ElementReader& r) : r_(r) {}

  bool has(const char* attr) const override { return r_.has(attr); }
  double number(const char* attr, double def, const NumberRule& rule) override {
    return r_.number(attr, def, rule);
  }
  Vec3 vector(const char* attr, const Vec3& def) override { return r_.vector(attr, def); }
  Vec3 direction(const char* attr, const Vec3& def) override { return r_.direction(attr, def); }
  bool boolean(const char* attr, bool def) override { return r_.boolean(attr, def); }
  Color color(const char* attr, const Color& def, bool* scalar) override {
    return r_.color(attr, def, scalar);
  }
  size_t choice(const char* attr, size_t def, const std::vector<std::string_view>& names) override;
  std::optional<std::string> text(const char* attr) override { return r_.text(attr); }
  std::optional<std::vector<double>> numbers(const char* attr) override;
  std::optional<std::vector<long long>> integers(const char* attr) override;
  std::optional<FunctionInput> function(const char* attr,
                                        const std::vector<std::string>& variables) override;
  std::shared_ptr<const MeshData> meshFile(const char* attr, bool* firstRead) override;
  std::shared_ptr<const HeightMap> heightMapFile(const char* attr, std::string& resolved) override;
  std::optional<std::string> filePath(const char* attr) override;
  // The child's attributes are those the element's shape entry declares for it.
  void forEachChild(const char* element, const std::function<void(AttributeInput&)>& read) override;

  void attrError(const char* attr, const std::string& message) override {
    r_.attrError(attr, message);
  }
  void error(const std::string& message) override { r_.error(message); }
  void warning(const std::string& message) override { r_.warning(message); }
  bool failed() const override { return r_.failed(); }

 private:
  ElementReader& r_;
};

}  // namespace lucent
