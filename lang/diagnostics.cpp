#include "diagnostics.h"

namespace lucent {

std::string Diagnostic::str() const {
  return loc.str() + (severity == Severity::Error ? ": error: " : ": warning: ") + message;
}

void Diagnostics::error(const SourceLoc& loc, std::string message) {
  all_.push_back({Severity::Error, loc, std::move(message)});
  ++errorCount_;
}

void Diagnostics::warning(const SourceLoc& loc, std::string message) {
  all_.push_back({Severity::Warning, loc, std::move(message)});
}

}  // namespace lucent
