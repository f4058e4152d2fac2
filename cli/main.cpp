// lucent: render, check, export-pov and compare scene files.
#include "commands.h"

#include "lang/did_you_mean.h"
#include "lang/parameters.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdio>
#include <cstring>

using namespace lucent;
using namespace lucent::cli;

namespace {

const std::vector<std::string_view> kCommands{"render", "check", "export-pov", "compare", "schema"};

// Help is --help in every command: -h is the image height (the contract's -h/--height).
void setHelp(CLI::App* app) { app->set_help_flag("--help", "Print this help and exit"); }

// DIR or DIR:DIR:...: each part must be an existing folder (a typo would silently allow
// nothing).
std::vector<std::string> splitPathList(const std::string& list) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    size_t colon = list.find(':', start);
    std::string part = list.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
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

// The -D list as a map; a malformed or repeated name is wrong usage (a scene parameter
// name can never be '1x', and of two values one would be silently lost).
void splitDefines(const std::vector<std::string>& defines, CommonOptions& common) {
  for (const std::string& d : defines) {
    auto eq = d.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError(fmt::format("-D expects name=value, got '{}'", d));
    std::string name = d.substr(0, eq);
    if (!Parameters::isValidName(name))
      throw UsageError(fmt::format("-D {}: a parameter name is letters, digits and '_', not "
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

// The first argument names the command; a misspelled one gets a hint (CLI11 alone would
// only say that a command is required).
bool checkCommandName(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "-h") == 0) {
    fmt::print(stderr, "lucent: error: -h is the image height (lucent render -h 480); help is "
                       "lucent --help\n");
    return false;
  }
  if (argc < 2 || argv[1][0] == '-') return true;
  for (std::string_view c : kCommands)
    if (c == argv[1]) return true;
  std::string hint = didYouMean(argv[1], kCommands);
  std::string list;  // "render, check, ... and schema", from the one list of commands
  for (size_t i = 0; i < kCommands.size(); ++i)
    list += (i == 0 ? "" : i + 1 == kCommands.size() ? " and " : ", ") + std::string(kCommands[i]);
  fmt::print(stderr, "lucent: error: unknown command '{}'{}; the commands are {} (lucent --help)\n",
             argv[1], hint, list);
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Lucent: a ray tracer for scenes written as XML files"};
  setHelp(&app);
  app.require_subcommand(1);
  app.set_version_flag("--version", "lucent 0.1");

  CommonOptions common;
  std::vector<std::string> defines, allowPaths;

  RenderOptions render;
  CLI::App* renderCmd = app.add_subcommand("render", "Render a scene to an image");
  setHelp(renderCmd);
  renderCmd->add_option("scene", render.scene, "Scene file (.xml)")->required();
  renderCmd->add_option("-o,--output", render.output,
                        "Output image; the format follows the extension (png exr tif jpg hdr "
                        "ppm). Default: SCENE.png beside the scene");
  renderCmd->add_option("-w,--width", render.width, "Image width in pixels");
  renderCmd->add_option("-h,--height", render.height, "Image height in pixels");
  renderCmd->add_option("-s,--samples", render.samples, "Samples per pixel");
  renderCmd->add_option("-t,--threads", render.threads, "Threads (default: all cores)");
  renderCmd->add_option("--max-depth", render.maxDepth, "Maximum recursion depth");
  renderCmd->add_option("--camera", render.camera, "Render through the camera with this name");
  renderCmd->add_flag("-q,--quiet", render.quiet, "No progress bar or closing line (warnings stay)");
  renderCmd->add_flag("--stats", render.stats,
                      "Print ray counts, time and Mrays/s (and each frame's time in an animation)");
  renderCmd->add_option("--frames", render.frames,
                        "Render only these frames of an animation: F or A..B (default: all)")
      ->type_name("A..B");
  renderCmd->add_option("--region", render.region,
                        "Render only these pixels of the image (right and bottom bounds excluded), "
                        "written as an image of their size")
      ->type_name("X0,Y0,X1,Y1");
  renderCmd->add_option("--tile-size", render.tileSize,
                        "Pixels a side of the tiles a checkpoint keeps (default 32, or 128 with adaptive supersampling of centres)");
  renderCmd->add_flag("--resume", render.resume,
                      "Continue an interrupted render from the checkpoint beside its output");
  renderCmd->add_option("--checkpoint-interval", render.checkpointInterval,
                        "Seconds between saves of the checkpoint (default 60; 0: keep none)");
  renderCmd->add_option("--tile-costs", render.tileCosts,
                        "Write each tile's render time to FILE (for bench/tile_schedule)")
      ->type_name("FILE");
  addCommonOptions(renderCmd, defines, allowPaths);

  CheckOptions check;
  CLI::App* checkCmd = app.add_subcommand("check", "Parse and validate a scene; print a summary");
  setHelp(checkCmd);
  checkCmd->add_option("scene", check.scene, "Scene file (.xml)")->required();
  checkCmd->add_option("-w,--width", check.width, "Validate for this image width (as render -w)");
  checkCmd->add_option("-h,--height", check.height, "Validate for this image height (as render -h)");
  checkCmd->add_option("-s,--samples", check.samples, "Samples per pixel (as render -s)");
  checkCmd->add_option("--max-depth", check.maxDepth, "Maximum recursion depth (as render)");
  checkCmd->add_option("--camera", check.camera, "Validate the camera with this name");
  addCommonOptions(checkCmd, defines, allowPaths);

  ExportPovOptions exportPov;
  CLI::App* exportCmd =
      app.add_subcommand("export-pov", "Write the scene as an equivalent POV-Ray 3.7 scene");
  setHelp(exportCmd);
  exportCmd->add_option("scene", exportPov.scene, "Scene file (.xml)")->required();
  exportCmd->add_option("-o,--output", exportPov.output, "POV-Ray scene to write (.pov)")
      ->required();
  exportCmd->add_option("-w,--width", exportPov.width, "Image width the camera is set up for");
  exportCmd->add_option("-h,--height", exportPov.height, "Image height the camera is set up for");
  exportCmd->add_option("--max-depth", exportPov.maxDepth, "Maximum recursion depth");
  exportCmd->add_option("--camera", exportPov.camera, "Export the camera with this name");
  exportCmd->add_option("--frame", exportPov.frame, "Export this frame of an animation (default 1)");
  addCommonOptions(exportCmd, defines, allowPaths);

  CompareOptions compare;
  CLI::App* compareCmd = app.add_subcommand(
      "compare", "Render with Lucent and POV-Ray; write both images, a heat map and a report");
  setHelp(compareCmd);
  compareCmd->add_option("scene", compare.scene, "Scene file (.xml)")->required();
  compareCmd->add_option("-o,--output", compare.outputDir, "Folder for the images and reports")
      ->required();
  compareCmd->add_option("--pov", compare.povFile,
                         "Compare against this hand-written POV-Ray scene instead of the export");
  compareCmd->add_option("-w,--width", compare.width, "Image width in pixels");
  compareCmd->add_option("-h,--height", compare.height, "Image height in pixels");
  compareCmd->add_option("-s,--samples", compare.samples,
                         "Samples per pixel (default 1: pixel centres in both renderers)");
  compareCmd->add_option("-t,--threads", compare.threads, "Threads for both renderers");
  compareCmd->add_option("--max-depth", compare.maxDepth, "Maximum recursion depth");
  compareCmd->add_option("--camera", compare.camera, "Render through the camera with this name");
  compareCmd->add_option("--frame", compare.frame, "Compare this frame of an animation (default 1)");
  addCommonOptions(compareCmd, defines, allowPaths);

  std::string schemaOutput;
  CLI::App* schemaCmd =
      app.add_subcommand("schema", "Print the scene language's XML Schema (docs/lucent.xsd)");
  setHelp(schemaCmd);
  schemaCmd->add_option("-o,--output", schemaOutput, "Write it to this file instead");

  if (!checkCommandName(argc, argv)) return kUsage;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version exit 0; every real usage error exits 1 (the contract's status).
    int status = app.exit(e);
    return status == 0 ? kOk : kUsage;
  }

  try {
    for (const CLI::App* cmd : app.get_subcommands())
      if (std::vector<std::string> extras = cmd->remaining(); !extras.empty())
        throw UsageError(unexpectedArguments(cmd, extras) + fmt::format(
                             "\nRun 'lucent {} --help' for more information.", cmd->get_name()));
    splitDefines(defines, common);
    for (const std::string& list : allowPaths)
      for (std::string& dir : splitPathList(list)) common.allowPaths.push_back(std::move(dir));

    if (*renderCmd) return runRender(render, common);
    if (*checkCmd) return runCheck(check, common);
    if (*exportCmd) return runExportPov(exportPov, common);
    if (*compareCmd) return runCompare(compare, common);
    if (*schemaCmd) return runSchema(schemaOutput);
    return kUsage;
  } catch (...) {
    return reportFailure(std::current_exception());
  }
}
