// What an evaluation of a POV-Ray scene is given from outside: where includes are
// searched, the frame identifiers (clock...), the declared identifiers of the command line,
// the limits, and where #debug and #warning text goes.
#pragma once

#include "scenegraph/source_loc.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lucent {
class FileAccess;
}

namespace lucent::sdl {

// The output of #debug and #warning (and the core's own warnings).
class Output {
 public:
  virtual ~Output() = default;
  // #debug's text as written, no line end added (console_text.h prints it in POV-Ray's
  // lines).
  virtual void debug(const std::string& text) = 0;
  virtual void warning(const SourceLoc& loc, const std::string& message) = 0;
};

// Collects everything, for tests and for callers that print later.
class CollectedOutput : public Output {
 public:
  void debug(const std::string& text) override { debugText += text; }
  void warning(const SourceLoc& loc, const std::string& message) override {
    warnings.push_back(loc.str() + ": warning: " + message);
  }
  std::string debugText;
  std::vector<std::string> warnings;
};

// Bounds that make every evaluation end in bounded time and memory (docs/povray-import.md).
struct Limits {
  std::uint64_t tokens = 200'000'000;        // tokens read, directives and skipped ones included
  std::uint64_t loopIterations = 1'000'000;  // iterations of one #while or #for
  int macroDepth = 100;            // macro calls and include files open at once (POV-Ray: 100)
  int includeDepth = 32;           // include files open at once (POV-Ray: 32)
  int conditionDepth = 200;        // #if, #while... and macro calls open at once (POV-Ray: 200)
  size_t stringLength = 1 << 24;   // characters in one string value
  size_t arrayElements = 1 << 22;  // elements of one array
  size_t fileBytes = 1 << 26;      // bytes of a file #read reads, and #write writes in all
};

struct Options {
  // The folders #include searches, in order, after the folder of the scene: the
  // --pov-library folders, then POV-Ray's standard include folder.
  std::vector<std::filesystem::path> includeFolders = {"/usr/share/povray-3.7/include"};
  // When set, a file in the scene's own folder is read only if this grants it; files found
  // in includeFolders must lie inside the folder they were found in.
  const FileAccess* access = nullptr;

  // The frame identifiers as POV-Ray declares them (clock is a keyword; the others are
  // identifiers a scene may redeclare).
  double clock = 0;
  bool clockOn = false;
  double clockDelta = 0, initialClock = 0, finalClock = 0;
  double frameNumber = 0, initialFrame = 0, finalFrame = 0;
  int imageWidth = 320, imageHeight = 240;
  // Declared before the scene is read, as POV-Ray's Declare=NAME=VALUE.
  std::map<std::string, double> declared;

  // The folders #fopen may write into (--allow-write); none: writing is refused, as
  // POV-Ray's I/O restrictions refuse it outside permitted paths.
  std::vector<std::filesystem::path> writeFolders;

  // Features Lucent cannot render are left out, each kind said once with the count of its
  // places, instead of being errors (--skip-unsupported).
  bool skipUnsupported = false;

  Limits limits;
  Output* output = nullptr;  // nullptr: #debug and warnings go to stderr
};

}  // namespace lucent::sdl
