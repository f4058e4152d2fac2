#include "command_line.h"

#include "lang/did_you_mean.h"
#include "lang/parameters.h"

#include <fmt/core.h>

namespace lucent::cli {

namespace {

// DIR or DIR:DIR:...: each part must be an existing folder (a typo would silently allow
// nothing).
std::vector<std::string> splitPathList(const std::string& list) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    size_t colon = list.find(':', start);
    std::string part =
        list.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    if (!part.empty()) parts.push_back(part);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return parts;
}

const CLI::Validator kExistingFolders(
    [](std::string& list) -> std::string {
      for (const std::string& part : splitPathList(list))
        if (std::string e = CLI::ExistingDirectory(part); !e.empty()) return e;
      return std::string();
    },
    "");

// The -D list as a map; a malformed or repeated name is wrong usage (a scene parameter
// name can never be '1x', and of two values one would be silently lost).
void splitDefines(const std::vector<std::string>& defines, CommonOptions& common) {
  for (const std::string& d : defines) {
    auto eq = d.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError(fmt::format("-D expects name=value, got '{}'", d));
    std::string name = d.substr(0, eq);
    if (!Parameters::isValidName(name))
      throw UsageError(
          fmt::format("-D {}: a parameter name is letters, digits and '_', not "
                      "starting with a digit; got '{}'",
                      d, name));
    auto [it, inserted] = common.defines.emplace(name, d.substr(eq + 1));
    if (!inserted)
      throw UsageError(fmt::format("-D {} is given twice ({}={} and {}); give it once", name, name,
                                   it->second, d));
  }
}

// The option names of a command, for "did you mean".
std::vector<std::string> optionNames(const CLI::App* app) {
  std::vector<std::string> names{"--help"};
  for (const CLI::Option* o : app->get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

}  // namespace

// Help is --help in every command: -h is the image height (the contract's -h/--height).
void setHelp(CLI::App* app) { app->set_help_flag("--help", "Print this help and exit"); }

// -D name=value, repeatable; the value may itself contain '='.
void addCommonOptions(CLI::App* app, std::vector<std::string>& defines,
                      std::vector<std::string>& allowPaths) {
  app->add_option("-D,--define", defines, "Set a scene parameter: -D name=value")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  app->add_option("--allow-path", allowPaths,
                  "Let the scene read files under these folders as well as its own "
                  "(a colon-separated list; repeatable)")
      ->type_name("DIR:DIR")
      ->check(kExistingFolders)
      ->allow_extra_args(false);
  // Unknown arguments are reported by main with a "did you mean".
  app->allow_extras();
}

void addPovOptions(CLI::App* app, CommonOptions& common) {
  app->add_option("--format", common.format,
                  "The scene's language: pov (POV-Ray 3.7) or xml (default: the extension "
                  "decides; .pov and .inc are POV-Ray's)")
      ->check(CLI::IsMember({"pov", "xml"}));
  app->add_option("--pov-library", common.povLibrary,
                  "POV-Ray scenes: a folder #include searches after the scene's own, before "
                  "the standard includes (as POV-Ray's +L; repeatable)")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory)
      ->allow_extra_args(false);
  app->add_option("--pov-ini", common.povIni,
                  "POV-Ray scenes: take the image size, Declare=, Library_Path and the "
                  "animation's frames and clock from this POV-Ray INI file (FILE[SECTION])")
      ->type_name("FILE");
  app->add_option("--allow-write", common.allowWrite,
                  "POV-Ray scenes: let #fopen write files in this folder (repeatable; "
                  "without it writing is refused)")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory)
      ->allow_extra_args(false);
  app->add_option("--pov-max-tokens", common.povMaxTokens,
                  "POV-Ray scenes: the most tokens the evaluation may read before the scene "
                  "is refused (default 200000000; loops and macros count each time)")
      ->type_name("N")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100'000'000'000}))
      ->allow_extra_args(false);
  app->add_flag("--skip-unsupported", common.skipUnsupported,
                "POV-Ray scenes: leave out what Lucent cannot render (said once per kind, "
                "with the count of places) instead of refusing the scene");
}

// Arguments the command does not take, as CLI11 words it. An unknown option comes first,
// alone (what follows it may be its value) and with a hint if it is a misspelling.
std::string unexpectedArguments(const CLI::App* app, const std::vector<std::string>& extras) {
  for (const std::string& e : extras) {
    if (e.size() < 2 || e[0] != '-') continue;
    const std::string word = e.substr(0, e.find('='));
    return "The following argument was not expected: " + e + didYouMean(word, optionNames(app));
  }
  std::string message = extras.size() == 1 ? "The following argument was not expected:"
                                           : "The following arguments were not expected:";
  for (const std::string& e : extras) message += " " + e;
  return message;
}

void takeCommonOptions(const std::vector<std::string>& defines,
                       const std::vector<std::string>& allowPaths, CommonOptions& common) {
  splitDefines(defines, common);
  for (const std::string& list : allowPaths)
    for (std::string& dir : splitPathList(list)) common.allowPaths.push_back(std::move(dir));
}

void addRenderOptions(CLI::App* app, RenderOptions& render) {
  app->add_option("scene", render.scene, "Scene file (.xml, or .pov: POV-Ray 3.7)")->required();
  app->add_option("-o,--output", render.output,
                  "Output image; the format follows the extension (png exr tif jpg hdr "
                  "ppm). Default: SCENE.png beside the scene");
  app->add_option("-w,--width", render.width, "Image width in pixels");
  app->add_option("-h,--height", render.height, "Image height in pixels");
  app->add_option("-s,--samples", render.samples, "Samples per pixel");
  app->add_option("-t,--threads", render.threads, "Threads (default: all cores)");
  app->add_option("--max-depth", render.maxDepth, "Maximum recursion depth");
  app->add_option("--camera", render.camera, "Render through the camera with this name");
  app->add_flag("-q,--quiet", render.quiet, "No progress bar or closing line (warnings stay)");
  app->add_flag("--stats", render.stats,
                "Print ray counts, time and Mrays/s (and each frame's time in an animation)");
  app->add_option("--frames", render.frames,
                  "Render only these frames of an animation: F or A..B (default: all)")
      ->type_name("A..B");
  app->add_option("--region", render.region,
                  "Render only these pixels of the image (right and bottom bounds excluded), "
                  "written as an image of their size")
      ->type_name("X0,Y0,X1,Y1");
  app->add_option("--tile-size", render.tileSize,
                  "Pixels a side of the tiles a checkpoint keeps (default 32, or 128 with adaptive "
                  "supersampling of centres)");
  app->add_flag("--resume", render.resume,
                "Continue an interrupted render from the checkpoint beside its output");
  app->add_option("--checkpoint-interval", render.checkpointInterval,
                  "Seconds between saves of the checkpoint (default 60; 0: keep none)");
  app->add_option("--tile-costs", render.tileCosts,
                  "Write each tile's render time to FILE (for bench/tile_schedule)")
      ->type_name("FILE");
}

}  // namespace lucent::cli
