// lucent: render, check, export-pov and compare scene files.
#include "command_line.h"
#include "commands.h"

#include "lang/did_you_mean.h"

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>

using namespace lucent;
using namespace lucent::cli;

namespace {

const std::vector<std::string_view> kCommands{"render", "check", "export-pov", "compare", "schema"};

// The first argument names the command; a misspelled one gets a hint (CLI11 alone would
// only say that a command is required).
bool checkCommandName(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "-h") == 0) {
    fmt::print(stderr,
               "lucent: error: -h is the image height (lucent render -h 480); help is "
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
  addRenderOptions(renderCmd, render);
  addCommonOptions(renderCmd, defines, allowPaths);

  CheckOptions check;
  CLI::App* checkCmd = app.add_subcommand("check", "Parse and validate a scene; print a summary");
  setHelp(checkCmd);
  checkCmd->add_option("scene", check.scene, "Scene file (.xml)")->required();
  checkCmd->add_option("-w,--width", check.width, "Validate for this image width (as render -w)");
  checkCmd->add_option("-h,--height", check.height,
                       "Validate for this image height (as render -h)");
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
  exportCmd->add_option("--frame", exportPov.frame,
                        "Export this frame of an animation (default 1)");
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
  compareCmd->add_option("--frame", compare.frame,
                         "Compare this frame of an animation (default 1)");
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
        throw UsageError(
            unexpectedArguments(cmd, extras) +
            fmt::format("\nRun 'lucent {} --help' for more information.", cmd->get_name()));
    takeCommonOptions(defines, allowPaths, common);

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
