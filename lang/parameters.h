// Scene parameters: `$name` and `${name}` in any attribute value are replaced by the value
// of <param name value> (declared at the top level of the scene or of an included file) or
// by -D name=value, which wins. A parameter's value may itself use other parameters
// (resolved when first used; cycles are errors). `$$` writes a literal '$'.
#pragma once

#include "diagnostics.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lucent {

class Parameters {
 public:
  Parameters(const std::map<std::string, std::string>& defines, Diagnostics& diags);

  // Names are letters, digits and '_', not starting with a digit.
  static bool isValidName(std::string_view name);

  // Declares a <param>; a second declaration of the same name is an error citing the first.
  void declare(const std::string& name, const std::string& rawValue, const SourceLoc& loc,
               const SourceLoc& valueLoc);

  // Replaces every parameter reference. On failure returns nullopt and sets `error` to a
  // message (without location) for the caller to report; `error` stays empty when the
  // failure is inside a parameter's own value, which is then reported at the <param>.
  std::optional<std::string> substitute(std::string_view text, std::string& error);

  // The -D names the scene never used (a likely typo on the command line).
  std::vector<std::string> unusedDefines() const;

 private:
  enum class State { Unresolved, Resolving, Resolved, Failed };
  struct Param {
    std::string raw;
    SourceLoc loc, valueLoc;
    State state = State::Unresolved;
    std::string value;
    bool used = false;
  };

  // The value of `name` (after -D and nested substitution); nullopt with error on failure.
  std::optional<std::string> lookup(const std::string& name, std::string& error);
  std::vector<std::string> knownNames() const;

  std::map<std::string, std::string> defines_;
  std::set<std::string> usedDefines_;
  std::unordered_map<std::string, Param> params_;
  std::vector<std::string> order_;     // declaration order, for messages
  std::vector<std::string> resolving_;  // the chain being resolved, to name cycles
  Diagnostics& diags_;
};

}  // namespace lucent
