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
  // An element inside a <repeat> is read once per instance: warn once, not a million times.
  if (!warned_.insert(loc.str() + '\n' + message).second) return;
  all_.push_back({Severity::Warning, loc, std::move(message)});
}

}  // namespace lucent
