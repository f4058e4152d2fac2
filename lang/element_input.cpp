#include "element_input.h"

#include "element_parsers.h"
#include "pigment_function_parser.h"

#include "expression_field.h"

#include "images/height_map_file.h"
#include "meshes/mesh_file_cache.h"
#include "scenegraph/shape_type.h"

namespace lucent {

size_t ElementInput::choice(const char* attr, size_t def,
                            const std::vector<std::string_view>& names) {
  std::vector<std::pair<std::string_view, size_t>> table;
  for (size_t i = 0; i < names.size(); ++i) table.emplace_back(names[i], i);
  return r_.choice(attr, def, table);
}

namespace {

// The list in attribute `attr`, read by `parse` (parseNumberList, parseIntegerList); a
// located error if it is not one.
template <class Parse>
auto readList(ElementReader& r, const char* attr, Parse parse)
    -> std::optional<std::decay_t<decltype(*parse(std::string()))>> {
  auto t = r.text(attr);
  if (!t) return std::nullopt;
  auto list = parse(*t);
  if (!list) {
    r.attrError(attr, list.error);
    return std::nullopt;
  }
  return *list;
}

}  // namespace

std::optional<std::vector<double>> ElementInput::numbers(const char* attr) {
  return readList(r_, attr, [](const std::string& t) { return parseNumberList(t); });
}

std::optional<std::vector<long long>> ElementInput::integers(const char* attr) {
  return readList(r_, attr, [](const std::string& t) { return parseIntegerList(t); });
}

std::optional<FunctionInput> ElementInput::function(const char* attr,
                                                    const std::vector<std::string>& variables) {
  // The element's <pigment-function> children are the pigments the function may call; when
  // one is wrong, the function's calls of it would only repeat that.
  bool pigmentsFailed = false;
  const auto pigments = parsePigmentFunctions(r_, pigmentsFailed);
  if (pigmentsFailed) {
    r_.markFailed();
    return std::nullopt;
  }
  std::optional<FunctionText> f = r_.function(attr, variables, pigments);
  if (!f) return std::nullopt;
  FunctionInput in;
  in.text = f->text;
  in.constants = f->constants;
  in.pigments = f->pigments;
  try {
    in.field = makeExpressionField(std::move(*f));
  } catch (...) {  // muParser's own errors were reported above; this is a safety net
    r_.attrError(attr, "cannot compile the function");
    return std::nullopt;
  }
  return in;
}

std::optional<uint32_t> ElementInput::material(const char* attr) {
  const pugi::xml_node inlined =
      inlineMaterial_ ? r_.element().child("material") : pugi::xml_node();
  if (inlined && r_.has(attr)) {
    const std::string at = r_.file().loc(inlined).str();
    r_.attrError(attr, "give either a '" + std::string(attr) +
                           "' attribute or an inline <material> child (at " + at + "), not both");
    return std::nullopt;
  }
  if (r_.has(attr)) return lookupMaterial(r_, attr);
  if (!inlined) return std::nullopt;
  ElementReader m(r_.ctx(), r_.file(), inlined);
  std::optional<uint32_t> index = parseInlineMaterial(m);
  if (m.failed()) r_.markFailed();
  return index;
}

std::optional<std::string> ElementInput::filePath(const char* attr) {
  auto src = r_.text(attr);
  if (!src) return std::nullopt;
  FileAccess::Resolved f = r_.ctx().files.resolve(*src, r_.file().folder());
  if (f.path.empty()) {
    r_.attrError(attr, f.error);
    return std::nullopt;
  }
  return f.path.string();
}

void ElementInput::forEachChild(const char* element,
                                const std::function<void(AttributeInput&)>& read) {
  const ChildElementInfo* info = nullptr;
  if (children_)
    for (const ChildElementInfo& c : *children_)
      if (c.name == element) {
        info = &c;
        break;
      }
  std::vector<std::string_view> allowed;
  if (info)
    for (const AttributeInfo& a : info->attributes) allowed.push_back(a.name);
  for (pugi::xml_node c = r_.element().child(element); c; c = c.next_sibling(element)) {
    ElementReader cr(r_.ctx(), r_.file(), c);
    cr.checkAttributes(allowed);
    const bool inlineMaterial = info && info->inlineMaterial;
    bool material = false;  // one <material>, where the child may hold one
    cr.forEachChild([&](pugi::xml_node g) {
      const bool isMaterial = std::string_view(g.name()) == "material";
      if (inlineMaterial && isMaterial && !material) {
        material = true;
        return;
      }
      ElementReader(r_.ctx(), r_.file(), g)
          .error(inlineMaterial && isMaterial
                     ? "only one <material> is allowed inside " + cr.tag()
                     : "<" + std::string(g.name()) + "> is not allowed inside " + cr.tag());
      cr.markFailed();
    });
    ElementInput in(cr, nullptr, inlineMaterial);
    read(in);
    if (cr.failed()) r_.markFailed();
  }
}

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

}  // namespace lucent
