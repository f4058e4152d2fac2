// Scene parameters and expressions in attribute values (contract, "Lexical rules" and
// "Expressions"): `$name` and `${name}` are replaced by the value of the name visible where
// the attribute stands (a local <param>, a <repeat> variable, a top-level <param>, -D
// name=value which wins at the top level, or a built-in: clock, frame, frames, pi, e);
// any other text between `${` and `}` is an expression, evaluated (expression.h) and
// written back in the shortest form that reads back exactly. A parameter's value may use
// other names (resolved when first used; cycles are errors). `$$` writes a literal '$'.
#pragma once

#include "diagnostics.h"
#include "expression.h"
#include "scope.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lucent {

// A substitution that failed: the message (empty when it was already reported, inside a
// parameter's own value) and, when known, the offset within the text of the offending part.
struct SubstitutionError {
  std::string message;
  size_t offset = std::string::npos;
};

class Parameters {
 public:
  Parameters(const std::map<std::string, std::string>& defines, Diagnostics& diags);

  // Names are letters, digits and '_', not starting with a digit.
  static bool isValidName(std::string_view name);

  // Declares a top-level <param>; a second declaration of the same name is an error citing
  // the first.
  void declare(const std::string& name, const std::string& rawValue, const SourceFile& file,
               pugi::xml_node element);
  // The built-in names, which parameters of the same name hide.
  void setBuiltin(const std::string& name, double value);
  bool hasDefine(const std::string& name) const { return defines_.count(name) > 0; }
  // The -D value of `name`, if given; asking marks it used.
  const std::string* define(const std::string& name);

  // Replaces every reference in `text` as seen from `scope` (null: the top level).
  std::optional<std::string> substitute(std::string_view text, const Scope* scope,
                                        SubstitutionError& error);

  // A shortcut for numeric attributes: when `raw` is `count` numbers separated by spaces or
  // single commas, each a literal or one whole `${...}`, and every one evaluates to a number
  // the value syntax accepts, writes them to `out` and returns true. Anything else (an
  // error included) returns false and the caller takes the textual way, which reports it:
  // the numbers are the same either way, as substitution writes them back exactly.
  bool evaluateNumbers(std::string_view raw, const Scope* scope, double* out, size_t count);

  // A function expression (an isosurface's) with `variables` left free and its other names
  // resolved from `scope` now (expression.h, compileFunction).
  // `pigments`: the pigment functions it may call (expression.h, compileFunction).
  std::optional<FunctionText> function(
      std::string_view text, const Scope* scope, const std::vector<std::string>& variables,
      SubstitutionError& error,
      const std::vector<std::shared_ptr<const PigmentFunction>>& pigments = {});

  // Is `name` visible from `scope` (a parameter, a repeat variable, -D or a built-in)?
  // Returns a description ("the parameter declared at 3:5") or "" when it is not.
  std::string whatIs(std::string_view name, const Scope* scope);

  // While one lives, nothing is reported and no failure is remembered: for looking ahead
  // (counting what a repeat will make) without reporting twice what the reading reports.
  class Quiet {
   public:
    explicit Quiet(Parameters& p) : p_(p) { ++p_.quiet_; }
    ~Quiet() { --p_.quiet_; }
    Quiet(const Quiet&) = delete;
    Quiet& operator=(const Quiet&) = delete;

   private:
    Parameters& p_;
  };

  // The -D names the scene never used (a likely typo on the command line).
  std::vector<std::string> unusedDefines() const;

 private:
  enum class State { Unresolved, Resolving, Resolved, Failed };
  struct Param {
    std::string raw;
    const SourceFile* file = nullptr;
    pugi::xml_node element;
    State state = State::Unresolved;
    std::string value;
    int numberState = 0;  // 0 unknown, 1 a number, 2 not one number
    double number = 0.0;
    bool used = false;
  };
  class Names;  // ExpressionNames seen from a scope

  // The text `name` stands for from `scope`; nullopt with error on failure.
  std::optional<std::string> lookup(std::string_view name, const Scope* scope, std::string& error,
                                    bool& known);
  // The number `name` stands for, for expressions.
  std::optional<double> number(std::string_view name, const Scope* scope, std::string& error,
                               bool& known);
  std::optional<std::string> resolveTop(const std::string& name, Param& p, std::string& error);
  std::optional<std::string> resolveLocal(Scope& scope, LocalParam& p, std::string& error);
  std::vector<std::string> knownNames(const Scope* scope) const;
  void report(const SourceLoc& loc, std::string message);
  void reportInValue(const SourceFile& file, pugi::xml_node element, const std::string& name,
                     const SubstitutionError& inner);

  std::map<std::string, std::string> defines_;
  std::set<std::string> usedDefines_;
  std::unordered_map<std::string, Param> params_;
  std::vector<std::string> order_;      // declaration order, for messages
  std::vector<std::string> resolving_;  // the chain being resolved, to name cycles
  std::vector<std::pair<std::string, double>> builtins_;
  ExpressionEvaluator evaluator_;
  int quiet_ = 0;
  Diagnostics& diags_;
};

// A message that names where a <param> was declared: "file:line:col".
std::string paramLocation(const SourceFile& file, pugi::xml_node element);

}  // namespace lucent
