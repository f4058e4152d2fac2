// Loading the valid scenes of tests/lang/valid/ in a test: a scene that must parse with no
// diagnostic at all (the diagnostics are shown when it does not).
#pragma once

#include "../support/paths.h"
#include "../support/scene_text.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace lucent::testing {

inline std::filesystem::path validDir() {
  return std::filesystem::path(lucentSourceDir()) / "tests" / "lang" / "valid";
}

using lucent::test::messages;

inline std::unique_ptr<Scene> load(const std::string& name, const ParseOptions& options = {}) {
  ParseResult r = parseSceneFile((validDir() / name).string(), options);
  INFO(messages(r));
  REQUIRE(r.scene != nullptr);
  REQUIRE(r.diagnostics.all().empty());  // no warnings either
  return std::move(r.scene);
}

}  // namespace lucent::testing
