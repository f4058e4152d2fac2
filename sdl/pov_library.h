// The `pov:` library of the XML language (docs/scene-language.md, "POV-Ray's named colours
// and textures"): POV-Ray's standard colours, textures, pigments and materials, made from
// POV-Ray's own include files by this importer, so that `material="pov:T_Wood10"` means
// what `texture { T_Wood10 }` means in POV-Ray. The build runs it (povlib/) and compiles
// the text it gives into Lucent; nothing of it is written by hand.
#pragma once

#include "options.h"

#include <string>
#include <vector>

namespace lucent::sdl {

// POV-Ray's standard includes that the library is made of, in the order they are read.
const std::vector<std::string>& povLibraryIncludes();

struct PovLibraryText {
  std::string xml;  // a Lucent scene of <material id="pov:NAME"> and <pov-color> elements
  int colours = 0;
  int materials = 0;
  std::vector<std::string> materialNames;  // "pov:T_Wood10"...
  // The declarations left out, each with the reason (a feature Lucent cannot render).
  std::vector<std::string> leftOut;
};

// Reads the includes (searched in options.includeFolders) and makes the library. Throws
// std::runtime_error when they cannot be read at all.
PovLibraryText makePovLibrary(const Options& options);

}  // namespace lucent::sdl
