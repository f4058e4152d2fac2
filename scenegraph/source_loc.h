// Where a scene construct was written: file, line and column, for compiler-like errors.
#pragma once

#include <string>

namespace lucent {

struct SourceLoc {
  std::string file;
  int line = 0;  // 1-based; 0 when unknown
  int col = 0;   // 1-based

  // "file:line:col", or just "file" when the position is unknown.
  std::string str() const {
    if (line <= 0) return file;
    return file + ":" + std::to_string(line) + ":" + std::to_string(col);
  }
};

}  // namespace lucent
