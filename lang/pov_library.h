// The `pov:` names of the XML language: POV-Ray's standard colours (`color="pov:White"`)
// and textures (`material="pov:T_Wood10"`), as the POV-Ray importer made them from POV-Ray's
// include files when Lucent was built (sdl/pov_library.h, povlib/). The library's text is
// given by the program (povlib/register.h); it is parsed once, on the first `pov:` name.
#pragma once

#include "source_file.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lucent {

inline constexpr std::string_view kPovPrefix = "pov:";

void setPovLibraryText(std::string_view xml);

struct PovLibrary {
  explicit PovLibrary(std::string text);
  SourceFile file;  // "pov:library" in messages
  // By full name ("pov:T_Wood10"): the <material> element, and the colours' red, green,
  // blue, filter and transmit (linear, as POV-Ray's with assumed_gamma 1).
  std::unordered_map<std::string, pugi::xml_node> materials;
  std::unordered_map<std::string, std::array<float, 5>> colours;
  std::vector<std::string_view> materialNames, colourNames;  // sorted, for hints
};

// The library, or null when this program was given none.
const PovLibrary* povLibrary();

}  // namespace lucent
