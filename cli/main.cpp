// lucent: render, check, export-pov, convert, compare and preview scene files.
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

const std::vector<std::string_view> kCommands{"render",  "check",   "export-pov", "convert",
                                              "compare", "preview", "schema"};

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

// Every command's options as parsed, and the subcommand CLI11 matched.
struct Commands {
  std::vector<std::string> defines, allowPaths;  // -D and --allow-path, of any command
  CommonOptions pov;  // --format and the POV-Ray options, of the commands that read scenes
  RenderOptions render;
  CheckOptions check;
  ExportPovOptions exportPov;
  ConvertOptions convert;
  CompareOptions compare;
  PreviewOptions preview;
  std::string schemaOutput;
  CLI::App *renderCmd = nullptr, *checkCmd = nullptr, *exportCmd = nullptr, *compareCmd = nullptr,
           *convertCmd = nullptr, *schemaCmd = nullptr, *previewCmd = nullptr;
};

void addRender(CLI::App& app, Commands& c) {
  c.renderCmd = app.add_subcommand("render", "Render a scene to an image");
  setHelp(c.renderCmd);
  addRenderOptions(c.renderCmd, c.render);
  addCommonOptions(c.renderCmd, c.defines, c.allowPaths);
  addPovOptions(c.renderCmd, c.pov);
}

void addCheck(CLI::App& app, Commands& c) {
  CheckOptions& check = c.check;
  CLI::App* cmd = c.checkCmd =
      app.add_subcommand("check", "Parse and validate a scene; print a summary");
  setHelp(cmd);
  cmd->add_option("scene", check.scene, "Scene file (.xml, or .pov: POV-Ray 3.7)")->required();
  cmd->add_option("-w,--width", check.width, "Validate for this image width (as render -w)");
  cmd->add_option("-h,--height", check.height, "Validate for this image height (as render -h)");
  cmd->add_option("-s,--samples", check.samples, "Samples per pixel (as render -s)");
  cmd->add_option("--max-depth", check.maxDepth, "Maximum recursion depth (as render)");
  cmd->add_option("--camera", check.camera, "Validate the camera with this name");
  cmd->add_flag("--stats", check.stats,
                "Also print the CPU time of reading the scene (parsing or evaluating it, "
                "building and checking it)");
  addCommonOptions(cmd, c.defines, c.allowPaths);
  addPovOptions(cmd, c.pov);
}

void addExportPov(CLI::App& app, Commands& c) {
  ExportPovOptions& exportPov = c.exportPov;
  CLI::App* cmd = c.exportCmd =
      app.add_subcommand("export-pov", "Write the scene as an equivalent POV-Ray 3.7 scene");
  setHelp(cmd);
  cmd->add_option("scene", exportPov.scene, "Scene file (.xml)")->required();
  cmd->add_option("-o,--output", exportPov.output, "POV-Ray scene to write (.pov)")->required();
  cmd->add_option("-w,--width", exportPov.width, "Image width the camera is set up for");
  cmd->add_option("-h,--height", exportPov.height, "Image height the camera is set up for");
  cmd->add_option("--max-depth", exportPov.maxDepth, "Maximum recursion depth");
  cmd->add_option("--camera", exportPov.camera, "Export the camera with this name");
  cmd->add_option("--frame", exportPov.frame, "Export this frame of an animation (default 1)");
  addCommonOptions(cmd, c.defines, c.allowPaths);
}

void addConvert(CLI::App& app, Commands& c) {
  ConvertOptions& convert = c.convert;
  CLI::App* cmd = c.convertCmd =
      app.add_subcommand("convert", "Write the scene as read as an equivalent Lucent XML scene");
  setHelp(cmd);
  cmd->add_option("scene", convert.scene, "Scene file")->required();
  cmd->add_option("-o,--output", convert.output, "XML scene to write (.xml)")->required();
  cmd->add_option("--frame", convert.frame, "Convert this frame of an animation (default 1)");
  addCommonOptions(cmd, c.defines, c.allowPaths);
  addPovOptions(cmd, c.pov);
}

void addCompare(CLI::App& app, Commands& c) {
  CompareOptions& compare = c.compare;
  CLI::App* cmd = c.compareCmd = app.add_subcommand(
      "compare", "Render with Lucent and POV-Ray; write both images, a heat map and a report");
  setHelp(cmd);
  cmd->add_option("scene", compare.scene, "Scene file (.xml, or .pov: POV-Ray 3.7)")->required();
  cmd->add_option("-o,--output", compare.outputDir, "Folder for the images and reports")
      ->required();
  cmd->add_option("--pov", compare.povFile,
                  "Compare against this hand-written POV-Ray scene instead of the export");
  cmd->add_option("-w,--width", compare.width, "Image width in pixels");
  cmd->add_option("-h,--height", compare.height, "Image height in pixels");
  cmd->add_option("-s,--samples", compare.samples,
                  "Samples per pixel (default 1: pixel centres in both renderers)");
  cmd->add_option("-t,--threads", compare.threads, "Threads for both renderers");
  cmd->add_option("--max-depth", compare.maxDepth, "Maximum recursion depth");
  cmd->add_option("--camera", compare.camera, "Render through the camera with this name");
  cmd->add_option("--frame", compare.frame, "Compare this frame of an animation (default 1)");
  addCommonOptions(cmd, c.defines, c.allowPaths);
  addPovOptions(cmd, c.pov);
}

void addPreview(CLI::App& app, Commands& c) {
  PreviewOptions& preview = c.preview;
  CLI::App* cmd = c.previewCmd = app.add_subcommand(
      "preview", "Show a live render of the scene in the browser, rendered again on every save");
  setHelp(cmd);
  cmd->add_option("scene", preview.scene, "Scene file (.xml, or .pov: POV-Ray 3.7)")->required();
  cmd->add_option("-w,--width", preview.width, "Image width in pixels");
  cmd->add_option("-h,--height", preview.height, "Image height in pixels");
  cmd->add_option("-s,--samples", preview.samples, "Samples per pixel");
  cmd->add_option("-t,--threads", preview.threads, "Render threads (default: every core)");
  cmd->add_option("--max-depth", preview.maxDepth, "Maximum recursion depth");
  cmd->add_option("--camera", preview.camera, "Render through the camera with this name");
  cmd->add_option("--bind", preview.bind,
                  "Address to listen on (default 127.0.0.1: this machine only; the address "
                  "printed carries a secret token all the same)");
  cmd->add_option("--port", preview.port, "Port to listen on (default: a free one)");
  cmd->add_flag("--open", preview.open, "Open the address in the desktop's browser (xdg-open)");
  cmd->add_flag("--compare", preview.compare,
                "After each render, show POV-Ray's render of the scene and the difference "
                "beside it (as lucent compare)");
  addCommonOptions(cmd, c.defines, c.allowPaths);
  addPovOptions(cmd, c.pov);
}

void addSchema(CLI::App& app, Commands& c) {
  c.schemaCmd =
      app.add_subcommand("schema", "Print the scene language's XML Schema (docs/lucent.xsd)");
  setHelp(c.schemaCmd);
  c.schemaCmd->add_option("-o,--output", c.schemaOutput, "Write it to this file instead");
}

// Runs the command parsed; its exit status.
int runCommand(const CLI::App& app, Commands& c) {
  try {
    for (const CLI::App* cmd : app.get_subcommands())
      if (std::vector<std::string> extras = cmd->remaining(); !extras.empty())
        throw UsageError(
            unexpectedArguments(cmd, extras) +
            fmt::format("\nRun 'lucent {} --help' for more information.", cmd->get_name()));
    CommonOptions common;
    takeCommonOptions(c.defines, c.allowPaths, common);
    common.format = c.pov.format;
    common.povLibrary = c.pov.povLibrary;
    common.povIni = c.pov.povIni;
    common.skipUnsupported = c.pov.skipUnsupported;
    common.allowWrite = c.pov.allowWrite;
    common.povMaxTokens = c.pov.povMaxTokens;

    if (*c.renderCmd) return runRender(c.render, common);
    if (*c.checkCmd) return runCheck(c.check, common);
    if (*c.exportCmd) return runExportPov(c.exportPov, common);
    if (*c.convertCmd) return runConvert(c.convert, common);
    if (*c.compareCmd) return runCompare(c.compare, common);
    if (*c.previewCmd) return runPreview(c.preview, common);
    if (*c.schemaCmd) return runSchema(c.schemaOutput);
    return kUsage;
  } catch (...) {
    return reportFailure(std::current_exception());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Lucent: a ray tracer for scenes written as XML files"};
  setHelp(&app);
  app.require_subcommand(1);
  app.set_version_flag("--version", "lucent 0.1");
  Commands commands;
  addRender(app, commands);
  addCheck(app, commands);
  addExportPov(app, commands);
  addConvert(app, commands);
  addCompare(app, commands);
  addPreview(app, commands);
  addSchema(app, commands);

  if (!checkCommandName(argc, argv)) return kUsage;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version exit 0; every real usage error exits 1 (the contract's status).
    int status = app.exit(e);
    return status == 0 ? kOk : kUsage;
  }
  return runCommand(app, commands);
}
