// lucent schema [-o FILE]: prints the scene language's XML Schema (lang/schema.h), or
// writes it to FILE, replacing FILE only once the whole text is written.
#include "commands.h"
#include "exit_status.h"

#include "lang/schema.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>

namespace lucent::cli {

int runSchema(const std::string& output) {
  const std::string text = schemaText();
  if (output.empty()) {
    fmt::print("{}", text);
    return kOk;
  }
  namespace fs = std::filesystem;
  const fs::path target(output);
  const fs::path temporary = target.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::error_code ec;
      fs::remove(temporary, ec);
      throw IoFailure(fmt::format("cannot write '{}'", output));
    }
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(temporary, ec);
    throw IoFailure(fmt::format("cannot write '{}': {}", output, why));
  }
  return kOk;
}

}  // namespace lucent::cli
