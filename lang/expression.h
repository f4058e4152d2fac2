// Arithmetic expressions, the text between `${` and `}` that is not a plain name (contract,
// "Expressions"): compiled once per distinct text by muParser (Debian's libmuparser) with
// the contract's operators and functions, then evaluated with the names of the place where
// it stands. Errors carry the offset of the offending token within the expression.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace lucent {

// The names an expression may use where it is evaluated, supplied by the caller.
class ExpressionNames {
 public:
  virtual ~ExpressionNames() = default;
  // The number `name` stands for. On failure: nullopt and a message in `error`, or an
  // empty `error` when the problem was already reported (inside a parameter's own value).
  // `known` tells whether the name exists at all (for "unknown name" with did-you-mean).
  virtual std::optional<double> number(std::string_view name, std::string& error, bool& known) = 0;
  // Every name visible here, for did-you-mean hints.
  virtual std::vector<std::string> visibleNames() = 0;
};

struct ExpressionError {
  std::string message;
  size_t offset = 0;      // of the offending token, within the expression text
  bool reported = false;  // already reported elsewhere: the caller adds nothing
};

class ExpressionEvaluator {
 public:
  ExpressionEvaluator();
  ~ExpressionEvaluator();
  ExpressionEvaluator(const ExpressionEvaluator&) = delete;
  ExpressionEvaluator& operator=(const ExpressionEvaluator&) = delete;

  // Evaluates `text`; nullopt with `error` on any problem. The result is finite.
  std::optional<double> evaluate(std::string_view text, ExpressionNames& names,
                                 ExpressionError& error);

 private:
  struct Compiled;
  Compiled& compiled(std::string_view text);
  void locateFault(const Compiled& c, ExpressionError& error);

  // By text; a scene with very many distinct expressions clears it now and then, so that
  // its memory (a parser each) stays bounded.
  std::unordered_map<std::string_view, std::unique_ptr<Compiled>> cache_;
  // Characters the fault locator may still parse (locateFault).
  size_t locateBudget_ = 200'000;
};

struct PigmentFunction;  // scenegraph/pigment_function.h

// A function expression (an isosurface's): its text, the names that stay variables (x, y,
// z), the values of its other names, resolved once where it stands, and the pigments it
// may call by name with three arguments.
struct FunctionText {
  std::string text;
  std::vector<std::string> variables;
  std::vector<std::pair<std::string, double>> constants;
  std::vector<std::shared_ptr<const PigmentFunction>> pigments{};
};

// Checks `text` as an expression whose `variables` are left free and whose other names are
// looked up in `names` now; nullopt with `error` (located within the text) on a syntax
// error, an unknown function or name, or a name that is not a number. `pigments` may be
// called by name, each with three arguments; the result keeps those the text calls.
std::optional<FunctionText> compileFunction(
    std::string_view text, const std::vector<std::string>& variables, ExpressionNames& names,
    ExpressionError& error,
    const std::vector<std::shared_ptr<const PigmentFunction>>& pigments = {});

// Shortest decimal text that reads back as exactly `v` ("0.1", "3", "1e+21").
std::string formatNumber(double v);

}  // namespace lucent
