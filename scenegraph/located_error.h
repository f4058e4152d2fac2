// The one exception for a problem found in a scene after parsing (building the world,
// forming a camera's image, reading a texture, a limit such as transforms multiplying
// beyond double range). It carries the construct's SourceLoc so the command line prints
// it exactly like a parse error, "file:line:col: error: message".
#pragma once

#include "source_loc.h"

#include <stdexcept>
#include <string>

namespace lucent {

class LocatedError : public std::runtime_error {
 public:
  // What the problem is, for the exit status: the scene itself is invalid (2), or a file
  // it names cannot be read or decoded (3, an input failure).
  enum class Kind { InvalidScene, Input };

  LocatedError(SourceLoc loc, std::string message, Kind kind = Kind::InvalidScene)
      : std::runtime_error(loc.str() + ": error: " + message),
        loc_(std::move(loc)),
        message_(std::move(message)),
        kind_(kind) {}

  const SourceLoc& loc() const { return loc_; }
  // The message without the location and "error:" (what() has both).
  const std::string& message() const { return message_; }
  Kind kind() const { return kind_; }

 private:
  SourceLoc loc_;
  std::string message_;
  Kind kind_;
};

}  // namespace lucent
