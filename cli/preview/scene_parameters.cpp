#include "scene_parameters.h"

#include <pugixml.hpp>

#include <cmath>
#include <cstdlib>

namespace lucent::preview {

bool readNumber(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

std::vector<SceneParameter> numericParameters(const std::string& path) {
  std::vector<SceneParameter> found;
  pugi::xml_document document;
  if (!document.load_file(path.c_str())) return found;
  for (pugi::xml_node p = document.child("scene").child("param"); p; p = p.next_sibling("param")) {
    SceneParameter parameter{p.attribute("name").value(), 0.0};
    if (!parameter.name.empty() && readNumber(p.attribute("value").value(), parameter.declared))
      found.push_back(parameter);
  }
  return found;
}

}  // namespace lucent::preview
