#include "attribute_probe.h"

#include "xml_numbers.h"

namespace lucent {

const std::string* AttributeProbe::find(const std::string& attr) const {
  for (const auto& [name, text] : values)
    if (name == attr) return &text;
  return nullptr;
}

void AttributeProbe::record(const char* attr, std::string text) {
  if (!find(attr)) values.emplace_back(attr, std::move(text));
}

void AttributeProbe::cannot(const char* attr) {
  if (has(attr)) unwritable.emplace_back(attr);
}

// Every attribute is there, so that each reader asks for its value.
bool AttributeProbe::has(const char*) const { return true; }

double AttributeProbe::number(const char* attr, double def, const NumberRule&) {
  if (has(attr)) record(attr, xmlNumber(def));
  return def;
}

long long AttributeProbe::integer(const char* attr, long long def, long long, long long) {
  if (has(attr)) record(attr, std::to_string(def));
  return def;
}

Vec3 AttributeProbe::vector(const char* attr, const Vec3& def) {
  if (has(attr)) record(attr, xmlVector(def));
  return def;
}

Vec3 AttributeProbe::direction(const char* attr, const Vec3& def) { return vector(attr, def); }

bool AttributeProbe::boolean(const char* attr, bool def) {
  if (has(attr)) record(attr, def ? "true" : "false");
  return def;
}

Color AttributeProbe::color(const char* attr, const Color& def, bool* scalar) {
  // A colour read as one number (ambient multiplied by the texture) is written as one.
  if (has(attr))
    record(attr,
           scalar && *scalar ? xmlColor(def).substr(0, xmlColor(def).find(' ')) : xmlColor(def));
  return def;
}

size_t AttributeProbe::choice(const char* attr, size_t def,
                              const std::vector<std::string_view>& names) {
  if (has(attr)) {
    if (def < names.size()) record(attr, std::string(names[def]));
    else cannot(attr);
  }
  return def;
}

Mat4 AttributeProbe::transform(const char* attr, const Mat4& def) {
  if (has(attr)) record(attr, xmlMatrix(def));
  return def;
}

std::optional<std::string> AttributeProbe::text(const char* attr) {
  cannot(attr);
  return std::nullopt;
}
std::optional<std::vector<double>> AttributeProbe::numbers(const char* attr) {
  cannot(attr);
  return std::nullopt;
}
std::optional<std::vector<long long>> AttributeProbe::integers(const char* attr) {
  cannot(attr);
  return std::nullopt;
}
std::optional<FunctionInput> AttributeProbe::function(const char* attr,
                                                      const std::vector<std::string>&) {
  cannot(attr);
  return std::nullopt;
}
std::shared_ptr<const MeshData> AttributeProbe::meshFile(const char* attr, bool*) {
  cannot(attr);
  return nullptr;
}
std::shared_ptr<const HeightMap> AttributeProbe::heightMapFile(const char* attr, std::string&) {
  cannot(attr);
  return nullptr;
}
std::optional<std::string> AttributeProbe::filePath(const char* attr) {
  cannot(attr);
  return std::nullopt;
}
std::optional<uint32_t> AttributeProbe::material(const char* attr) {
  cannot(attr);
  return std::nullopt;
}
void AttributeProbe::forEachChild(const char* element,
                                  const std::function<void(AttributeInput&)>&) {
  unwritable.push_back(std::string("<") + element + ">");
}

}  // namespace lucent
