// Errors and warnings with their source location, printed like a compiler's.
#pragma once

#include "scenegraph/source_loc.h"

#include <string>
#include <unordered_set>
#include <vector>

namespace lucent {

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLoc loc;
  std::string message;

  // "file:line:col: error: message"
  std::string str() const;
};

class Diagnostics {
 public:
  void error(const SourceLoc& loc, std::string message);
  void warning(const SourceLoc& loc, std::string message);

  bool hasErrors() const { return errorCount_ > 0; }
  size_t errorCount() const { return errorCount_; }
  const std::vector<Diagnostic>& all() const { return all_; }

 private:
  std::vector<Diagnostic> all_;
  size_t errorCount_ = 0;
  std::unordered_set<std::string> warned_;  // location and message of each warning given
};

}  // namespace lucent
