// The attributes of a shape element, read through its entry in the shape registry
// (scenegraph/shape_registry.h): this file only connects the registry's AttributeInput to
// one XML element, and knows no shape by name.
#include "element_parsers.h"
#include "expression_field.h"

#include "images/height_map_file.h"
#include "meshes/mesh_file_cache.h"
#include "scenegraph/shape_registry.h"

namespace lucent {

namespace {

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
  size_t choice(const char* attr, size_t def, const std::vector<std::string_view>& names) override {
    std::vector<std::pair<std::string_view, size_t>> table;
    for (size_t i = 0; i < names.size(); ++i) table.emplace_back(names[i], i);
    return r_.choice(attr, def, table);
  }
  std::optional<std::string> text(const char* attr) override { return r_.text(attr); }
  std::optional<std::vector<double>> numbers(const char* attr) override {
    auto t = r_.text(attr);
    if (!t) return std::nullopt;
    auto list = parseNumberList(*t);
    if (!list) {
      r_.attrError(attr, list.error);
      return std::nullopt;
    }
    return *list;
  }
  std::optional<std::vector<long long>> integers(const char* attr) override {
    auto t = r_.text(attr);
    if (!t) return std::nullopt;
    auto list = parseIntegerList(*t);
    if (!list) {
      r_.attrError(attr, list.error);
      return std::nullopt;
    }
    return *list;
  }
  std::shared_ptr<const MeshData> meshFile(const char* attr, bool* firstRead) override;
  std::optional<FunctionInput> function(const char* attr,
                                        const std::vector<std::string>& variables) override {
    std::optional<FunctionText> f = r_.function(attr, variables);
    if (!f) return std::nullopt;
    FunctionInput in;
    in.text = f->text;
    in.constants = f->constants;
    try {
      in.field = makeExpressionField(std::move(*f));
    } catch (...) {  // muParser's own errors were reported above; this is a safety net
      r_.attrError(attr, "cannot compile the function");
      return std::nullopt;
    }
    return in;
  }

  std::optional<std::string> filePath(const char* attr) override {
    auto src = r_.text(attr);
    if (!src) return std::nullopt;
    FileAccess::Resolved f = r_.ctx().files.resolve(*src, r_.file().folder());
    if (f.path.empty()) {
      r_.attrError(attr, f.error);
      return std::nullopt;
    }
    return f.path.string();
  }
  std::shared_ptr<const HeightMap> heightMapFile(const char* attr, std::string& resolved) override;

  void forEachChild(const char* element,
                    const std::function<void(AttributeInput&)>& read) override {
    const ShapeType* t = findShapeType(r_.element().name());
    const ChildElementInfo* info = t ? t->child(element) : nullptr;
    std::vector<std::string_view> allowed;
    if (info)
      for (const AttributeInfo& a : info->attributes) allowed.push_back(a.name);
    for (pugi::xml_node c = r_.element().child(element); c; c = c.next_sibling(element)) {
      ElementReader cr(r_.ctx(), r_.file(), c);
      cr.checkAttributes(allowed);
      cr.forEachChild([&](pugi::xml_node g) {
        ElementReader(r_.ctx(), r_.file(), g)
            .error("<" + std::string(g.name()) + "> is not allowed inside " + cr.tag());
        cr.markFailed();
      });
      ElementInput in(cr);
      read(in);
      if (cr.failed()) r_.markFailed();
    }
  }

  void attrError(const char* attr, const std::string& message) override {
    r_.attrError(attr, message);
  }
  void error(const std::string& message) override { r_.error(message); }
  void warning(const std::string& message) override { r_.warning(message); }
  bool failed() const override { return r_.failed(); }

 private:
  ElementReader& r_;
};

// Each file is read once however many elements name it.
std::shared_ptr<const MeshData> ElementInput::meshFile(const char* attr, bool* firstRead) {
  if (firstRead) *firstRead = false;
  auto src = r_.text(attr);
  if (!src) return nullptr;
  FileAccess::Resolved f = r_.ctx().files.resolve(*src, r_.file().folder());
  if (f.path.empty()) {
    r_.attrError(attr, f.error);
    return nullptr;
  }
  try {
    return r_.ctx().meshCache->get(f.path.string(), firstRead);
  } catch (const std::exception& e) {  // MeshError, and anything a reader library throws
    r_.attrError(attr, "cannot read the mesh '" + *src + "': " + e.what());
    return nullptr;
  }
}

std::shared_ptr<const HeightMap> ElementInput::heightMapFile(const char* attr,
                                                             std::string& resolved) {
  auto src = r_.text(attr);
  if (!src) return nullptr;
  FileAccess::Resolved f = r_.ctx().files.resolve(*src, r_.file().folder());
  if (f.path.empty()) {
    r_.attrError(attr, f.error);
    return nullptr;
  }
  resolved = f.path.string();
  try {
    return readHeightMapFile(resolved);
  } catch (const std::exception& e) {  // HeightMapError, ImagePluginError, a library's own
    r_.attrError(attr, "cannot read the height field's image '" + *src + "': " + e.what());
    return nullptr;
  }
}

}  // namespace

bool isShapeElement(std::string_view name) { return findShapeType(name) != nullptr; }

std::vector<std::string_view> shapeAttributes(std::string_view element) {
  const ShapeType* t = findShapeType(element);
  return t ? t->attributeNames() : std::vector<std::string_view>{};
}

std::optional<ShapeSpec> parseShape(ElementReader& r) {
  const ShapeType* t = findShapeType(r.element().name());
  if (!t) return std::nullopt;
  ElementInput in(r);
  return t->read(in);
}

}  // namespace lucent
