// The command line shared by `lucent` (main.cpp) and `lucent-mpi` (mpi/main.cpp): the
// options every command takes, `render`'s options, and the words for what is not expected.
#pragma once

#include "commands.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace lucent::cli {

// Help is --help in every command: -h is the image height (the contract's -h/--height).
void setHelp(CLI::App* app);

// -D name=value (repeatable) and --allow-path DIR:DIR, kept as given until
// takeCommonOptions checks them.
void addCommonOptions(CLI::App* app, std::vector<std::string>& defines,
                      std::vector<std::string>& allowPaths);
// --format pov|xml, --pov-library DIR (repeatable), --pov-ini FILE[SECTION] and
// --skip-unsupported, for the commands that read POV-Ray scenes (load_pov_scene.h): written
// into `common` as parsed.
void addPovOptions(CLI::App* app, CommonOptions& common);
// Throws UsageError for a malformed or repeated -D.
void takeCommonOptions(const std::vector<std::string>& defines,
                       const std::vector<std::string>& allowPaths, CommonOptions& common);

// The scene, -o and every option of `lucent render`.
void addRenderOptions(CLI::App* app, RenderOptions& render);

// Arguments the command does not take, as CLI11 words it, with a "did you mean".
std::string unexpectedArguments(const CLI::App* app, const std::vector<std::string>& extras);

}  // namespace lucent::cli
