// POV-Ray scenes for the commands that read a scene (docs/povray-import.md): which files
// are POV-Ray's, and reading one through sdl/ into what the XML parser gives.
#pragma once

#include "commands.h"
#include "load_scene.h"

#include "lang/parser.h"

#include <string>

namespace lucent::cli {

// Whether `scene` is read as POV-Ray's language: `--format pov|xml` decides, or else the
// extension (.pov and .inc are POV-Ray's).
bool isPovScene(const std::string& scene, const std::string& format);

// The POV-Ray scene of `request` read with POV-Ray's meaning, at the image size POV-Ray
// would render it (800x600 unless -w/-h), -D values declared as POV-Ray's Declare= does.
// Throws UsageError for a -D value that is not a number.
ParseResult parsePovScene(const SceneRequest& request, const CommonOptions& common);

}  // namespace lucent::cli
