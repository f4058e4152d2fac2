// The scene language's AttributeInput (scenegraph/attribute_input.h): one XML element read
// through its ElementReader, so that the tables of scenegraph/ (the shape registry's
// fields, the camera, light and finish tables' readers) read attributes without knowing of XML.
#pragma once

#include "element_reader.h"

#include "scenegraph/attribute_input.h"

#include <vector>

namespace lucent {

struct ChildElementInfo;  // scenegraph/shape_type.h

class ElementInput final : public AttributeInput {
 public:
  // `children`: the child elements the element's reader may visit (forEachChild) and their
  // attributes; none when null.
  // `inlineMaterial`: the element may hold one <material> child, which material() reads.
  explicit ElementInput(ElementReader& r, const std::vector<ChildElementInfo>* children = nullptr,
                        bool inlineMaterial = false)
      : r_(r), children_(children), inlineMaterial_(inlineMaterial) {}

  bool has(const char* attr) const override { return r_.has(attr); }
  double number(const char* attr, double def, const NumberRule& rule) override {
    return r_.number(attr, def, rule);
  }
  long long integer(const char* attr, long long def, long long min, long long max) override {
    return r_.integer(attr, def, min, max);
  }
  Vec3 vector(const char* attr, const Vec3& def) override { return r_.vector(attr, def); }
  Vec3 direction(const char* attr, const Vec3& def) override { return r_.direction(attr, def); }
  using AttributeInput::color;
  using AttributeInput::signedColor;
  Color color(const char* attr, const Color& def, bool* scalar) override {
    return r_.color(attr, def, scalar);
  }
  Color signedColor(const char* attr, const Color& def, bool* scalar) override {
    return r_.color(attr, def, scalar, true);
  }
  bool boolean(const char* attr, bool def) override { return r_.boolean(attr, def); }
  size_t choice(const char* attr, size_t def, const std::vector<std::string_view>& names) override;
  Mat4 transform(const char* attr, const Mat4& def) override {
    return r_.has(attr) ? r_.transform(attr) : def;
  }
  std::optional<std::string> text(const char* attr) override { return r_.text(attr); }
  std::optional<std::vector<double>> numbers(const char* attr) override;
  std::optional<std::vector<long long>> integers(const char* attr) override;
  std::optional<FunctionInput> function(const char* attr,
                                        const std::vector<std::string>& variables) override;
  std::shared_ptr<const MeshData> meshFile(const char* attr, bool* firstRead) override;
  std::shared_ptr<const HeightMap> heightMapFile(const char* attr, std::string& resolved) override;
  std::optional<std::string> filePath(const char* attr) override;
  std::optional<uint32_t> material(const char* attr) override;
  void forEachChild(const char* element, const std::function<void(AttributeInput&)>& read) override;

  void attrError(const char* attr, const std::string& message) override {
    r_.attrError(attr, message);
  }
  void error(const std::string& message) override { r_.error(message); }
  void warning(const std::string& message) override { r_.warning(message); }
  bool failed() const override { return r_.failed(); }

 private:
  ElementReader& r_;
  const std::vector<ChildElementInfo>* children_;
  bool inlineMaterial_;
};

}  // namespace lucent
