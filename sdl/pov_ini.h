// POV-Ray's INI files (`--pov-ini FILE`): the keys that change what a scene evaluates to or
// the image it is framed for, read as POV-Ray reads them (docs/povray-import.md, "Commands").
// Keys that only change how POV-Ray renders or writes (antialiasing, output files,
// display) are listed as not taken; a key POV-Ray does not know is an error.
#pragma once

#include "scenegraph/source_loc.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

struct PovIni {
  std::optional<int> width, height;            // Width=, +W
  std::map<std::string, double> declared;      // Declare=NAME=VALUE
  std::vector<std::filesystem::path> library;  // Library_Path=, +L (relative to the ini's folder)
  std::optional<std::string> inputFile;        // Input_File_Name=, relative to the ini's folder
  // The animation: frames initialFrame..finalFrame, clock from initialClock to finalClock.
  std::optional<int> initialFrame, finalFrame;
  std::optional<double> initialClock, finalClock;
  std::optional<double> clock;  // Clock=, +K: the clock of a single frame
  bool cyclic = false;          // Cyclic_Animation
  // Keys read and not taken (they change how POV-Ray renders or writes, not the scene),
  // each with where it was written.
  std::vector<std::pair<std::string, SourceLoc>> notTaken;

  bool animated() const { return finalFrame && *finalFrame > initialFrame.value_or(1); }
};

// Reads `path` (an INI file; `section` names the part to read: empty for the lines before
// the first [label], as POV-Ray reads a file named without a label). Throws LocatedError
// at the line of a malformed or unknown entry, or naming the file when it cannot be read.
PovIni readPovIni(const std::filesystem::path& path, const std::string& section = {});
// The same for text held in memory, `name` naming it in messages.
PovIni readPovIniText(const std::string& name, const std::string& text,
                      const std::string& section = {});

}  // namespace lucent::sdl
