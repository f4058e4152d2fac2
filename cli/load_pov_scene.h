// POV-Ray scenes for the commands that read a scene (docs/povray-import.md): which files
// are POV-Ray's, and reading one through sdl/ into what the XML parser gives.
#pragma once

#include "commands.h"
#include "load_scene.h"

#include "lang/parser.h"
#include "sdl/pov_ini.h"

#include <string>

namespace lucent::cli {

// Whether `scene` is read as POV-Ray's language: `--format pov|xml` decides, or else the
// extension (.pov and .inc are POV-Ray's).
bool isPovScene(const std::string& scene, const std::string& format);

// The POV-Ray scene of `request` read with POV-Ray's meaning, at the image size POV-Ray
// would render it (800x600 unless -w/-h), -D values declared as POV-Ray's Declare= does.
// Throws UsageError for a -D value that is not a number.
// With --pov-ini FILE, the animation's frames and clocks, -w/-h, Declare= and library
// folders come from that file (sdl/pov_ini.h); -w/-h, -D and --pov-library given on the
// command line win over it.
ParseResult parsePovScene(const SceneRequest& request, const CommonOptions& common);

// The INI file of --pov-ini (FILE or FILE[SECTION]) read; empty without one. Throws
// UsageError, located in the file, for one that cannot be read.
sdl::PovIni readIniOption(const CommonOptions& common);

}  // namespace lucent::cli
