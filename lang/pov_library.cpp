#include "pov_library.h"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <sstream>

namespace lucent {

namespace {

std::string_view& registeredText() {
  static std::string_view text;
  return text;
}

std::array<float, 5> colourOf(pugi::xml_node c) {
  std::array<float, 5> v{};
  std::istringstream rgb(c.attribute("rgb").value());
  rgb >> v[0] >> v[1] >> v[2];
  v[3] = c.attribute("filter").as_float();
  v[4] = c.attribute("transmit").as_float();
  return v;
}

}  // namespace

void setPovLibraryText(std::string_view xml) { registeredText() = xml; }

PovLibrary::PovLibrary(std::string text) : file("pov:library", ".", std::move(text)) {
  // The build made the text and checked it: a failure here is a broken build.
  if (file.parse()) std::abort();
  for (pugi::xml_node n : file.root().children()) {
    const std::string id = n.attribute("id").value();
    if (std::string_view(n.name()) == "material") materials.emplace(id, n);
    else if (std::string_view(n.name()) == "pov-color") colours.emplace(id, colourOf(n));
  }
  for (const auto& [name, node] : materials) materialNames.push_back(name);
  for (const auto& [name, c] : colours) colourNames.push_back(name);
  std::sort(materialNames.begin(), materialNames.end());
  std::sort(colourNames.begin(), colourNames.end());
}

const PovLibrary* povLibrary() {
  static std::once_flag once;
  static std::unique_ptr<const PovLibrary> library;
  std::call_once(once, [] {
    if (!registeredText().empty())
      library = std::make_unique<const PovLibrary>(std::string(registeredText()));
  });
  return library.get();
}

}  // namespace lucent
