#include "expression.h"

#include "scenegraph/internal_functions.h"

#include "did_you_mean.h"
#include "expression_functions.h"
#include "pigment_call.h"

#include "scenegraph/pigment_function.h"

#include <fmt/format.h>
#include <muParser.h>

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

constexpr size_t kMaxCachedExpressions = 4096;

bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNameChar(char c) { return isNameStart(c) || isDigit(c); }

// A name in the text (not a parse: muParser parses; this only finds where names stand).
struct NameToken {
  std::string_view name;
  size_t offset;
  bool call;  // followed by '('
};

std::vector<NameToken> scanNames(std::string_view t) {
  std::vector<NameToken> out;
  for (size_t i = 0; i < t.size();) {
    char c = t[i];
    if (isDigit(c) || (c == '.' && i + 1 < t.size() && isDigit(t[i + 1]))) {  // a number
      while (i < t.size() && (isDigit(t[i]) || t[i] == '.')) ++i;
      if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        size_t j = i + 1;
        if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
        if (j < t.size() && isDigit(t[j])) {
          i = j;
          while (i < t.size() && isDigit(t[i])) ++i;
        }
      }
      continue;
    }
    if (isNameStart(c)) {
      size_t j = i;
      while (j < t.size() && isNameChar(t[j])) ++j;
      size_t k = j;
      while (k < t.size() && (t[k] == ' ' || t[k] == '\t')) ++k;
      out.push_back({t.substr(i, j - i), i, k < t.size() && t[k] == '('});
      i = j;
      continue;
    }
    ++i;
  }
  return out;
}

bool isFunction(std::string_view name) {
  const auto& f = expressionFunctionNames();
  return std::find(f.begin(), f.end(), name) != f.end();
}

std::string arity(std::string_view fn) {
  if (const InternalFunction* f = internalFunctionNamed(fn))
    return std::to_string(f->params) + " arguments";
  if (fn == "atan2" || fn == "pow" || fn == "random") return "2 arguments";
  if (fn == "clamp" || fn == "mix") return "3 arguments";
  if (fn == "min" || fn == "max") return "1 or more arguments";
  return "1 argument";
}

// muParser's message for a syntax error, reworded and without its own position.
ExpressionError syntaxError(const mu::ParserError& e, std::string_view text,
                            const std::vector<NameToken>& names) {
  ExpressionError err;
  size_t pos = std::min<size_t>(static_cast<size_t>(std::max(0, e.GetPos())), text.size());
  std::string token = e.GetToken();
  if (auto sp = token.find(' '); sp != std::string::npos) token.resize(sp);
  switch (e.GetCode()) {
    case mu::ecTOO_FEW_PARAMS:
    case mu::ecTOO_MANY_PARAMS: {
      // The call is the last occurrence of the function's name before the position.
      size_t at = pos;
      for (const NameToken& n : names)
        if (n.call && n.name == token && n.offset < pos) at = n.offset;
      err.offset = at;
      err.message = fmt::format("{} arguments for '{}' (it takes {})",
                                e.GetCode() == mu::ecTOO_FEW_PARAMS ? "too few" : "too many", token,
                                arity(token));
      return err;
    }
    case mu::ecUNEXPECTED_EOF:
      err.message = "the expression ends too early";
      err.offset = text.empty() ? 0 : text.size() - 1;
      while (err.offset > 0 && text[err.offset] == ' ') --err.offset;
      return err;
    case mu::ecMISSING_PARENS:
      err.message = "a '(' is not closed";
      err.offset = text.rfind('(') == std::string_view::npos ? 0 : text.rfind('(');
      return err;
    case mu::ecMISSING_ELSE_CLAUSE:
      err.message = "'?' without its ':'";
      err.offset = text.find('?') == std::string_view::npos ? pos : text.find('?');
      return err;
    default:
      break;
  }
  if (pos >= text.size()) {
    // muParser places some errors past the last character ("1 + -", "!", "a:"), naming a
    // token that is not there: the expression stops where it still needs something.
    err.message = "the expression ends too early";
    size_t last = text.find_last_not_of(" \t\n\r");
    err.offset = last == std::string_view::npos ? 0 : last;
    return err;
  }
  err.offset = pos;
  err.message = token.empty() ? "syntax error" : "unexpected '" + token + "'";
  // "- -x": muParser reads the unary operators of a run written together only.
  size_t at = text.empty() ? 0 : std::min(pos, text.size() - 1);
  while (at > 0 && text[at] != '-' && text[at] != '!') --at;  // muParser may point past it
  if (!token.empty() && (token[0] == '-' || token[0] == '!') && at > 0) {
    size_t before = text.find_last_not_of(" \t\n\r", at - 1);
    if (before != std::string_view::npos && before + 1 < at &&
        (text[before] == '-' || text[before] == '!'))
      err.message +=
          "; write unary operators in a row without spaces (--x, !-x) or with parentheses (-(-x))";
  }
  return err;
}

}  // namespace

struct ExpressionEvaluator::Compiled {
  std::string text;
  mu::Parser parser;
  std::vector<std::string> names;        // the names it uses, in muParser's order
  std::vector<size_t> nameOffsets;       // where each is first written
  std::unique_ptr<double[]> slots;       // their values, bound to the parser
  std::vector<NameToken> tokens;         // into `text`
  std::optional<ExpressionError> error;  // a syntax error: every evaluation reports it
};

ExpressionEvaluator::ExpressionEvaluator() = default;
ExpressionEvaluator::~ExpressionEvaluator() = default;

std::string formatNumber(double v) { return fmt::format("{}", v); }

ExpressionEvaluator::Compiled& ExpressionEvaluator::compiled(std::string_view text) {
  if (auto it = cache_.find(text); it != cache_.end()) return *it->second;
  if (cache_.size() >= kMaxCachedExpressions) cache_.clear();
  auto c = std::make_unique<Compiled>();
  c->text = std::string(text);
  c->tokens = scanNames(c->text);
  auto fail = [&](std::string message, size_t offset) {
    if (!c->error) c->error = ExpressionError{std::move(message), offset, false};
  };
  std::string_view t = c->text;
  if (t.find_first_not_of(" \t") == std::string_view::npos) fail("an empty expression", 0);
  if (auto d = t.find('$'); d != std::string_view::npos)
    fail("inside ${...} a parameter is written by its name alone ('r', not '$r')", d);
  for (const NameToken& n : c->tokens) {
    if (n.call && !isFunction(n.name))
      fail("unknown function '" + std::string(n.name) + "'" +
               didYouMean(n.name, expressionFunctionNames()),
           n.offset);
    else if (!n.call && isFunction(n.name))
      fail("'" + std::string(n.name) + "' is a function: write " + std::string(n.name) + "(...)",
           n.offset);
  }
  if (!c->error) {
    try {
      defineLanguage(c->parser, ParserRole::Plain);
      c->parser.SetExpr(c->text);
      const mu::varmap_type& used = c->parser.GetUsedVar();
      c->slots = std::make_unique<double[]>(std::max<size_t>(1, used.size()));
      size_t k = 0;
      for (const auto& entry : used) {
        c->names.push_back(entry.first);
        size_t offset = 0;
        for (const NameToken& n : c->tokens)
          if (!n.call && n.name == entry.first) {
            offset = n.offset;
            break;
          }
        c->nameOffsets.push_back(offset);
        c->slots[k] = 0.0;
        ++k;
      }
      for (size_t i = 0; i < c->names.size(); ++i) c->parser.DefineVar(c->names[i], &c->slots[i]);
    } catch (const mu::ParserError& e) {
      c->error = syntaxError(e, c->text, c->tokens);
    }
  }
  Compiled& ref = *c;
  cache_.emplace(std::string_view(ref.text), std::move(c));
  return ref;
}

std::optional<double> ExpressionEvaluator::evaluate(std::string_view text, ExpressionNames& names,
                                                    ExpressionError& error) {
  Compiled& c = compiled(text);
  if (c.error) {
    error = *c.error;
    return std::nullopt;
  }
  for (size_t i = 0; i < c.names.size(); ++i) {
    std::string message;
    bool known = true;
    std::optional<double> v = names.number(c.names[i], message, known);
    if (v) {
      c.slots[i] = *v;
      continue;
    }
    error.offset = c.nameOffsets[i];
    error.reported = known && message.empty();
    error.message = known ? message
                          : "unknown name '" + c.names[i] + "' in expression" +
                                didYouMean(c.names[i], names.visibleNames());
    return std::nullopt;
  }
  ExpressionFault& fault = currentExpressionFault();
  fault.happened = false;
  double r;
  try {
    r = c.parser.Eval();
  } catch (const mu::ParserError& e) {
    error = syntaxError(e, c.text, c.tokens);
    return std::nullopt;
  }
  if (fault.happened || !std::isfinite(r)) {
    locateFault(c, error);
    return std::nullopt;
  }
  return r;
}

// Which occurrence faulted: each operator and function in turn is replaced by its twin,
// which throws when it is the one that faults with finite arguments (a fault that only
// carries a non-finite value further is not the origin). Only runs on an error.
void ExpressionEvaluator::locateFault(const Compiled& c, ExpressionError& error) {
  const ExpressionFault& fault = currentExpressionFault();
  error.message = fault.happened ? fault.what : "the result is not a finite number";
  error.offset = 0;
  mu::Parser locator;
  defineLanguage(locator, ParserRole::Locating);
  auto faultsWith = [&](const std::string& variant) {
    locateBudget_ -= std::min(locateBudget_, variant.size());
    try {
      locator.ClearVar();
      for (size_t i = 0; i < c.names.size(); ++i) locator.DefineVar(c.names[i], &c.slots[i]);
      locator.SetExpr(variant);
      locator.Eval();
    } catch (const mu::ParserError&) {
      return false;  // the twin does not fit here (a unary '-', say)
    } catch (...) {
      return true;
    }
    return false;
  };
  // Each try parses the whole text again, so locating is quadratic in its length: past the
  // evaluator's budget (well under a second of parsing) the fault is reported at the start of the
  // expression, so that long faulty expressions (a 20,000-character one took minutes) or
  // thousands of them cannot stall the scene's loading.
  size_t next = 0;  // the first token at or after p (tokens are in text order)
  for (size_t p = 0; p < c.text.size() && locateBudget_ > 0; ++p) {
    while (next < c.tokens.size() && c.tokens[next].offset < p) ++next;
    for (size_t k = next; k < c.tokens.size() && c.tokens[k].offset == p && locateBudget_ > 0; ++k)
      if (const NameToken& n = c.tokens[k]; n.call) {
        std::string variant = c.text;
        variant.insert(p, 1, kFunctionTwinPrefix);
        if (faultsWith(variant)) {
          error.offset = p;
          error.message = fault.what;  // the twin's own record, also when muParser folded it
          return;
        }
      }
    for (const OperatorTwin& t : faultingOperators())
      if (c.text[p] == t.op && locateBudget_ > 0) {
        std::string variant = c.text;
        variant[p] = t.twin;
        if (faultsWith(variant)) {
          error.offset = p;
          error.message = fault.what;  // the twin's own record, also when muParser folded it
          return;
        }
      }
  }
}

std::optional<FunctionText> compileFunction(
    std::string_view text, const std::vector<std::string>& variables, ExpressionNames& names,
    ExpressionError& error, const std::vector<std::shared_ptr<const PigmentFunction>>& pigments) {
  FunctionText out;
  out.text = std::string(text);
  out.variables = variables;
  const std::vector<NameToken> tokens = scanNames(out.text);
  std::string_view t = out.text;
  auto fail = [&](std::string message, size_t offset) {
    error = ExpressionError{std::move(message), offset, false};
    return std::nullopt;
  };
  if (t.find_first_not_of(" \t\n\r") == std::string_view::npos)
    return fail("an empty expression", 0);
  if (auto d = t.find('$'); d != std::string_view::npos)
    return fail("a function's names are written alone ('r', not '$r')", d);
  auto pigmentNamed = [&](std::string_view name) -> std::shared_ptr<const PigmentFunction> {
    for (const auto& p : pigments)
      if (p->name == name) return p;
    return nullptr;
  };
  for (const NameToken& n : tokens) {
    if (const auto p = pigmentNamed(n.name)) {
      if (!n.call)
        return fail("'" + std::string(n.name) + "' is a pigment function: write " +
                        std::string(n.name) + "(x, y, z)",
                    n.offset);
      if (std::find(out.pigments.begin(), out.pigments.end(), p) == out.pigments.end())
        out.pigments.push_back(p);
      continue;
    }
    if (n.call && !isFunction(n.name)) {
      std::vector<std::string_view> known = expressionFunctionNames();
      for (const auto& p : pigments) known.push_back(p->name);
      return fail("unknown function '" + std::string(n.name) + "'" + didYouMean(n.name, known),
                  n.offset);
    }
    if (!n.call && isFunction(n.name))
      return fail(
          "'" + std::string(n.name) + "' is a function: write " + std::string(n.name) + "(...)",
          n.offset);
  }
  std::vector<std::string> used;
  try {
    mu::Parser parser;
    defineLanguage(parser, ParserRole::Plain);
    definePigmentFunctions(parser, out.pigments);
    parser.SetExpr(out.text);
    for (const auto& entry : parser.GetUsedVar()) used.push_back(entry.first);
  } catch (const mu::ParserError& e) {
    error = syntaxError(e, out.text, tokens);
    if (e.GetCode() == mu::ecTOO_FEW_PARAMS || e.GetCode() == mu::ecTOO_MANY_PARAMS) {
      std::string token = e.GetToken();
      if (auto sp = token.find(' '); sp != std::string::npos) token.resize(sp);
      if (pigmentNamed(token))  // a pigment function takes the point
        error.message = (e.GetCode() == mu::ecTOO_FEW_PARAMS ? "too few" : "too many") +
                        std::string(" arguments for '") + token +
                        "' (a pigment function takes 3 arguments: x, y and z)";
    }
    return std::nullopt;
  }
  for (const std::string& name : used) {
    if (std::find(variables.begin(), variables.end(), name) != variables.end()) continue;
    size_t offset = 0;
    for (const NameToken& n : tokens)
      if (!n.call && n.name == name) {
        offset = n.offset;
        break;
      }
    std::string message;
    bool known = true;
    std::optional<double> v = names.number(name, message, known);
    if (v) {
      out.constants.emplace_back(name, *v);
      continue;
    }
    error.offset = offset;
    error.reported = known && message.empty();
    if (known) {
      error.message = message;
    } else {
      std::vector<std::string> visible = names.visibleNames();
      visible.insert(visible.end(), variables.begin(), variables.end());
      error.message = "unknown name '" + name + "' in the function (its variables are ";
      for (size_t i = 0; i < variables.size(); ++i)
        error.message += (i ? (i + 1 == variables.size() ? " and " : ", ") : "") + variables[i];
      error.message += "; other names are parameters)" + didYouMean(name, visible);
    }
    return std::nullopt;
  }
  return out;
}

}  // namespace lucent
