// lucent: render, check, export-pov and compare scene files.
#include "commands.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdio>

using namespace lucent::cli;

namespace {

// -D name=value, repeatable; the value may itself contain '='.
void addCommonOptions(CLI::App* app, CommonOptions& common, std::vector<std::string>& defines) {
  app->add_option("-D,--define", defines, "Set a scene parameter: -D name=value")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  // A folder that does not exist is a typo: say so rather than silently allow nothing.
  app->add_option("--allow-path", common.allowPaths,
                  "Let the scene read files under DIR as well as its own folder")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory)
      ->allow_extra_args(false);
}

bool splitDefines(const std::vector<std::string>& defines, CommonOptions& common) {
  for (const std::string& d : defines) {
    auto eq = d.find('=');
    if (eq == std::string::npos || eq == 0) {
      fmt::print(stderr, "lucent: error: -D expects name=value, got '{}'\n", d);
      return false;
    }
    common.defines[d.substr(0, eq)] = d.substr(eq + 1);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Lucent: a ray tracer for scenes written as XML files"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "lucent 0.1");

  CommonOptions common;
  std::vector<std::string> defines;

  RenderOptions render;
  CLI::App* renderCmd = app.add_subcommand("render", "Render a scene to an image");
  renderCmd->add_option("scene", render.scene, "Scene file (.xml)")->required();
  renderCmd->add_option("-o,--output", render.output,
                        "Output image; the format follows the extension (png exr tif jpg hdr ppm)")
      ->required();
  // -h is the image height (as the contract says); help is --help only.
  renderCmd->set_help_flag("--help", "Print this help and exit");
  renderCmd->add_option("-w,--width", render.width, "Image width in pixels");
  renderCmd->add_option("-h,--height", render.height, "Image height in pixels");
  renderCmd->add_option("-s,--samples", render.samples, "Samples per pixel");
  renderCmd->add_option("-t,--threads", render.threads, "Threads (default: all cores)");
  renderCmd->add_option("--max-depth", render.maxDepth, "Maximum recursion depth");
  renderCmd->add_option("--camera", render.camera, "Render through the camera with this name");
  renderCmd->add_flag("-q,--quiet", render.quiet, "No progress or messages");
  renderCmd->add_flag("--stats", render.stats, "Print ray counts, time and Mrays/s");
  addCommonOptions(renderCmd, common, defines);

  std::string checkScene;
  CLI::App* checkCmd = app.add_subcommand("check", "Parse and validate a scene; print a summary");
  checkCmd->add_option("scene", checkScene, "Scene file (.xml)")->required();
  addCommonOptions(checkCmd, common, defines);

  ExportPovOptions exportPov;
  CLI::App* exportCmd =
      app.add_subcommand("export-pov", "Write the scene as an equivalent POV-Ray 3.7 scene");
  exportCmd->add_option("scene", exportPov.scene, "Scene file (.xml)")->required();
  exportCmd->add_option("-o,--output", exportPov.output, "POV-Ray scene to write (.pov)")
      ->required();
  exportCmd->set_help_flag("--help", "Print this help and exit");
  exportCmd->add_option("-w,--width", exportPov.width, "Image width the camera is set up for");
  exportCmd->add_option("-h,--height", exportPov.height, "Image height the camera is set up for");
  exportCmd->add_option("--max-depth", exportPov.maxDepth, "Maximum recursion depth");
  exportCmd->add_option("--camera", exportPov.camera, "Export the camera with this name");
  addCommonOptions(exportCmd, common, defines);

  CompareOptions compare;
  CLI::App* compareCmd = app.add_subcommand(
      "compare", "Render with Lucent and POV-Ray; write both images, a heat map and a report");
  compareCmd->add_option("scene", compare.scene, "Scene file (.xml)")->required();
  compareCmd->add_option("-o,--output", compare.outputDir, "Folder for the images and reports")
      ->required();
  compareCmd->add_option("--pov", compare.povFile,
                         "Compare against this hand-written POV-Ray scene instead of the export");
  compareCmd->set_help_flag("--help", "Print this help and exit");
  compareCmd->add_option("-w,--width", compare.width, "Image width in pixels");
  compareCmd->add_option("-h,--height", compare.height, "Image height in pixels");
  compareCmd->add_option("-s,--samples", compare.samples,
                         "Samples per pixel (default 1: pixel centres in both renderers)");
  compareCmd->add_option("-t,--threads", compare.threads, "Threads for both renderers");
  compareCmd->add_option("--max-depth", compare.maxDepth, "Maximum recursion depth");
  compareCmd->add_option("--camera", compare.camera, "Render through the camera with this name");
  addCommonOptions(compareCmd, common, defines);

  std::string schemaOutput;
  CLI::App* schemaCmd =
      app.add_subcommand("schema", "Print the scene language's XML Schema (docs/lucent.xsd)");
  schemaCmd->add_option("-o,--output", schemaOutput, "Write it to this file instead");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version exit 0; every real usage error exits 1 (the contract's status).
    int status = app.exit(e);
    return status == 0 ? kOk : kUsage;
  }
  if (!splitDefines(defines, common)) return kUsage;

  if (*renderCmd) return runRender(render, common);
  if (*checkCmd) return runCheck(checkScene, common);
  if (*exportCmd) return runExportPov(exportPov, common);
  if (*compareCmd) return runCompare(compare, common);
  if (*schemaCmd) return runSchema(schemaOutput);
  return kUsage;
}
