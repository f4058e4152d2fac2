#include "parameters.h"

#include "did_you_mean.h"
#include "values.h"

#include <charconv>
#include <cmath>

namespace lucent {

namespace {
// A parameter's value may use another's, resolved when first used, recursively: a chain
// of 100,000 parameters each naming the next must be an error, not a stack overflow.
constexpr size_t kMaxParameterDepth = 1000;

bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }

std::string_view trimSpaces(std::string_view s) {
  size_t b = s.find_first_not_of(" \t\n\r");
  if (b == std::string_view::npos) return {};
  size_t e = s.find_last_not_of(" \t\n\r");
  return s.substr(b, e - b + 1);
}

// A parameter's value read as one number for an expression; the state caches the answer.
std::optional<double> asNumber(std::string_view name, const std::string& value, int& state,
                               double& number, std::string& error) {
  if (state == 0) {
    Parsed<double> n = parseNumber(value);
    state = n ? 1 : 2;
    if (n) number = *n;
  }
  if (state == 1) return number;
  std::string shown = value.size() > 40 ? value.substr(0, 40) + "..." : value;
  error = "the parameter '" + std::string(name) + "' is '" + shown +
          "', not one number, so it cannot be used in an expression";
  return std::nullopt;
}
}  // namespace

std::string paramLocation(const SourceFile& file, pugi::xml_node element) {
  return file.loc(element).str();
}

class Parameters::Names final : public ExpressionNames {
 public:
  Names(Parameters& p, const Scope* scope) : p_(p), scope_(scope) {}
  std::optional<double> number(std::string_view name, std::string& error, bool& known) override {
    return p_.number(name, scope_, error, known);
  }
  std::vector<std::string> visibleNames() override { return p_.knownNames(scope_); }

 private:
  Parameters& p_;
  const Scope* scope_;
};

Parameters::Parameters(const std::map<std::string, std::string>& defines, Diagnostics& diags)
    : defines_(defines), diags_(diags) {
  builtins_ = {{"pi", M_PI}, {"e", M_E}, {"clock", 0.0}, {"frame", 1.0}, {"frames", 1.0}};
}

std::optional<FunctionText> Parameters::function(
    std::string_view text, const Scope* scope, const std::vector<std::string>& variables,
    SubstitutionError& error, const std::vector<std::shared_ptr<const PigmentFunction>>& pigments) {
  Names names(*this, scope);
  ExpressionError e;
  std::optional<FunctionText> f = compileFunction(text, variables, names, e, pigments);
  if (!f) {
    error.message = e.reported || quiet_ ? "" : e.message;
    error.offset = e.offset;
  }
  return f;
}

bool Parameters::isValidName(std::string_view name) {
  if (name.empty() || !isNameStart(name[0])) return false;
  for (char c : name)
    if (!isNameChar(c)) return false;
  return true;
}

void Parameters::declare(const std::string& name, const std::string& rawValue,
                         const SourceFile& file, pugi::xml_node element) {
  auto [it, inserted] = params_.try_emplace(name);
  if (!inserted) {
    diags_.error(file.loc(element), "<param> '" + name +
                                        "' is already declared (first declared at " +
                                        paramLocation(*it->second.file, it->second.element) + ")");
    return;
  }
  it->second.raw = rawValue;
  it->second.file = &file;
  it->second.element = element;
  order_.push_back(name);
}

void Parameters::setBuiltin(const std::string& name, double value) {
  for (auto& [n, v] : builtins_)
    if (n == name) {
      v = value;
      return;
    }
  builtins_.emplace_back(name, value);
}

const std::string* Parameters::define(const std::string& name) {
  auto it = defines_.find(name);
  if (it == defines_.end()) return nullptr;
  usedDefines_.insert(name);
  return &it->second;
}

std::vector<std::string> Parameters::knownNames(const Scope* scope) const {
  std::vector<std::string> names;
  for (const Scope* s = scope; s; s = s->parent.get()) {
    if (!s->var.empty()) names.emplace_back(s->var);
    for (const LocalParam& p : s->params) names.emplace_back(p.name);
  }
  names.insert(names.end(), order_.begin(), order_.end());
  for (const auto& [name, value] : defines_)
    if (!params_.count(name)) names.push_back(name);
  // pi and e are left out: a one-letter typo is rarely meant as e.
  for (const auto& [name, value] : builtins_)
    if (name != "e" && name != "pi") names.push_back(name);
  return names;
}

void Parameters::reportInValue(const SourceFile& file, pugi::xml_node element,
                               const std::string& name, const SubstitutionError& inner) {
  pugi::xml_attribute value = element.attribute("value");
  SourceLoc where = inner.offset != std::string::npos
                        ? file.locInValue(value, element, inner.offset)
                        : file.valueLoc(value, element);
  report(where, "<param> '" + name + "' attribute 'value': " + inner.message);
}

void Parameters::report(const SourceLoc& loc, std::string message) {
  if (!quiet_) diags_.error(loc, std::move(message));
}

std::optional<std::string> Parameters::resolveTop(const std::string& name, Param& p,
                                                  std::string& error) {
  (void)error;
  switch (p.state) {
    case State::Resolved:
      return p.value;
    case State::Failed:
      return std::nullopt;  // already reported at the <param>
    case State::Resolving: {
      std::string chain;
      for (const std::string& n : resolving_) chain += n + " -> ";
      report(p.file->loc(p.element), "<param> '" + name + "' refers to itself: " + chain + name);
      p.state = quiet_ ? State::Unresolved : State::Failed;
      return std::nullopt;
    }
    case State::Unresolved:
      break;
  }
  if (resolving_.size() >= kMaxParameterDepth) {
    report(p.file->loc(p.element), "<param> '" + name +
                                       "': parameters refer to one another more than " +
                                       std::to_string(kMaxParameterDepth) + " deep here");
    p.state = quiet_ ? State::Unresolved : State::Failed;
    return std::nullopt;
  }
  p.state = State::Resolving;
  resolving_.push_back(name);
  SubstitutionError inner;
  std::optional<std::string> value = substitute(p.raw, nullptr, inner);
  resolving_.pop_back();
  if (!value) {
    if (!inner.message.empty()) reportInValue(*p.file, p.element, name, inner);
    p.state = quiet_ ? State::Unresolved : State::Failed;
    return std::nullopt;
  }
  if (p.state == State::Failed) return std::nullopt;  // a cycle through it was reported
  p.state = State::Resolved;
  p.value = *value;
  return p.value;
}

std::optional<std::string> Parameters::resolveLocal(Scope& scope, LocalParam& p,
                                                    std::string& error) {
  if (p.aliasScope) return resolveLocal(*p.aliasScope, p.aliasScope->params[p.aliasIndex], error);
  std::string name(p.name);
  switch (p.state) {
    case LocalParam::State::Resolved:
      return p.value;
    case LocalParam::State::Failed:
      return std::nullopt;
    case LocalParam::State::Resolving: {
      std::string chain;
      for (const std::string& n : resolving_) chain += n + " -> ";
      report(p.file->loc(p.element), "<param> '" + name + "' refers to itself: " + chain + name);
      p.state = quiet_ ? LocalParam::State::Unresolved : LocalParam::State::Failed;
      return std::nullopt;
    }
    case LocalParam::State::Unresolved:
      break;
  }
  if (resolving_.size() >= kMaxParameterDepth) {
    report(p.file->loc(p.element), "<param> '" + name +
                                       "': parameters refer to one another more than " +
                                       std::to_string(kMaxParameterDepth) + " deep here");
    p.state = quiet_ ? LocalParam::State::Unresolved : LocalParam::State::Failed;
    return std::nullopt;
  }
  p.state = LocalParam::State::Resolving;
  resolving_.push_back(name);
  SubstitutionError inner;
  // Its siblings are visible, except for a <use>'s arguments.
  std::optional<std::string> value =
      substitute(p.raw, p.readOutside ? p.outside.get() : &scope, inner);
  resolving_.pop_back();
  if (!value) {
    if (!inner.message.empty()) reportInValue(*p.file, p.element, name, inner);
    p.state = quiet_ ? LocalParam::State::Unresolved : LocalParam::State::Failed;
    return std::nullopt;
  }
  if (p.state == LocalParam::State::Failed) return std::nullopt;
  p.state = LocalParam::State::Resolved;
  p.value = *value;
  return p.value;
}

std::optional<std::string> Parameters::lookup(std::string_view name, const Scope* scope,
                                              std::string& error, bool& known) {
  known = true;
  for (const Scope* s = scope; s; s = s->parent.get()) {
    if (!s->var.empty() && s->var == name) return formatNumber(s->value);
    for (LocalParam& p : const_cast<Scope*>(s)->params)
      if (p.name == name) return resolveLocal(*const_cast<Scope*>(s), p, error);
  }
  std::string key(name);
  auto it = params_.find(key);
  if (it != params_.end()) it->second.used = true;
  if (auto d = defines_.find(key); d != defines_.end()) {
    usedDefines_.insert(key);
    return d->second;  // -D wins, taken literally
  }
  if (it != params_.end()) return resolveTop(key, it->second, error);
  for (const auto& [n, v] : builtins_)
    if (n == name) return formatNumber(v);
  known = false;
  error = "undefined parameter '" + key + "'" + didYouMean(key, knownNames(scope)) +
          "; declare it with <param name=\"" + key + "\" value=\"...\"/> or -D " + key + "=...";
  return std::nullopt;
}

std::optional<double> Parameters::number(std::string_view name, const Scope* scope,
                                         std::string& error, bool& known) {
  known = true;
  for (const Scope* s = scope; s; s = s->parent.get()) {
    if (!s->var.empty() && s->var == name) return s->value;
    for (LocalParam& p : const_cast<Scope*>(s)->params) {
      if (p.name != name) continue;
      Scope* owner = const_cast<Scope*>(s);
      LocalParam* q = &p;
      while (q->aliasScope) {
        owner = q->aliasScope.get();
        q = &owner->params[q->aliasIndex];
      }
      if (q->numberState == 1) return q->number;
      std::optional<std::string> v = resolveLocal(*owner, *q, error);
      if (!v) return std::nullopt;
      return asNumber(name, *v, q->numberState, q->number, error);
    }
  }
  std::string key(name);
  auto it = params_.find(key);
  if (it != params_.end() && !defines_.count(key)) {
    Param& p = it->second;
    if (p.numberState == 1) {
      p.used = true;
      return p.number;
    }
  }
  std::optional<std::string> v = lookup(name, nullptr, error, known);
  if (!v) return std::nullopt;
  if (it != params_.end() && !defines_.count(key))
    return asNumber(name, *v, it->second.numberState, it->second.number, error);
  int state = 0;
  double n = 0.0;
  return asNumber(name, *v, state, n, error);
}

std::string Parameters::whatIs(std::string_view name, const Scope* scope) {
  for (const Scope* s = scope; s; s = s->parent.get()) {
    if (!s->var.empty() && s->var == name)
      return "the variable of the <repeat> at " + s->file->loc(s->element).str();
    for (const LocalParam& p : s->params)
      if (p.name == name) return "a parameter declared at " + p.file->loc(p.element).str();
  }
  std::string key(name);
  if (auto it = params_.find(key); it != params_.end())
    return "the parameter declared at " + it->second.file->loc(it->second.element).str();
  if (defines_.count(key)) return "a parameter given with -D";
  for (const auto& [n, v] : builtins_)
    if (n == name) return "a built-in name";
  return "";
}

std::optional<std::string> Parameters::substitute(std::string_view text, const Scope* scope,
                                                  SubstitutionError& error) {
  if (text.find('$') == std::string_view::npos) return std::string(text);
  std::string out;
  out.reserve(text.size() + 16);
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c != '$') {
      out += c;
      ++i;
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '$') {
      out += '$';
      i += 2;
      continue;
    }
    std::string message;
    bool known = true;
    if (i + 1 < text.size() && text[i + 1] == '{') {
      size_t close = text.find('}', i + 2);
      if (close == std::string_view::npos) {
        error = {"'${' without a closing '}'", i};
        return std::nullopt;
      }
      std::string_view inside = text.substr(i + 2, close - i - 2);
      std::string_view name = trimSpaces(inside);
      if (isValidName(name)) {
        std::optional<std::string> value = lookup(name, scope, message, known);
        if (!value) {
          error = {message, i + 2 + static_cast<size_t>(name.data() - inside.data())};
          return std::nullopt;
        }
        out += *value;
      } else {
        Names names(*this, scope);
        ExpressionError e;
        std::optional<double> v = evaluator_.evaluate(inside, names, e);
        if (!v) {
          error = {e.reported ? std::string() : e.message, i + 2 + e.offset};
          return std::nullopt;
        }
        out += formatNumber(*v);
      }
      i = close + 1;
      continue;
    }
    size_t j = i + 1;
    while (j < text.size() && isNameChar(text[j])) ++j;
    std::string_view name = text.substr(i + 1, j - i - 1);
    if (!isValidName(name)) {
      error = {"'$' must be followed by a parameter name or {name} (write $$ for a literal '$')",
               i};
      return std::nullopt;
    }
    std::optional<std::string> value = lookup(name, scope, message, known);
    if (!value) {
      error = {message, i + 1};
      return std::nullopt;
    }
    out += *value;
    i = j;
  }
  return out;
}

bool Parameters::evaluateNumbers(std::string_view raw, const Scope* scope, double* out,
                                 size_t count) {
  auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  auto acceptable = [](double v) {
    return std::isfinite(v) && std::abs(v) <= 1e30 && (v == 0.0 || std::abs(v) >= 1e-30);
  };
  size_t n = 0, i = 0;
  while (i < raw.size() && isSpace(raw[i])) ++i;
  while (i < raw.size()) {
    if (n == count) return false;
    double v;
    if (raw[i] == '$') {
      if (i + 1 >= raw.size() || raw[i + 1] != '{') return false;
      size_t close = raw.find('}', i + 2);
      if (close == std::string_view::npos) return false;
      std::string_view inside = raw.substr(i + 2, close - i - 2);
      std::string_view name = trimSpaces(inside);
      std::optional<double> x;
      if (isValidName(name)) {
        std::string message;
        bool known = true;
        x = number(name, scope, message, known);
      } else {
        Names names(*this, scope);
        ExpressionError e;
        x = evaluator_.evaluate(inside, names, e);
      }
      if (!x) return false;
      v = *x;
      i = close + 1;
    } else {
      size_t end = i;
      while (end < raw.size() && !isSpace(raw[end]) && raw[end] != ',' && raw[end] != '$') ++end;
      if (end == i || raw[i] == '+') return false;
      auto [p, ec] = std::from_chars(raw.data() + i, raw.data() + end, v);
      if (ec != std::errc() || p != raw.data() + end) return false;
      i = end;
    }
    if (!acceptable(v)) return false;
    out[n++] = v;
    // A separator: spaces, or one comma with optional spaces around it; none at the end.
    size_t j = i;
    while (j < raw.size() && isSpace(raw[j])) ++j;
    if (j < raw.size() && raw[j] == ',') {
      ++j;
      while (j < raw.size() && isSpace(raw[j])) ++j;
      if (j == raw.size()) return false;
    }
    if (j == i && j < raw.size()) return false;  // "1${a}": glued together
    i = j;
  }
  return n == count;
}

std::vector<std::string> Parameters::unusedDefines() const {
  std::vector<std::string> unused;
  for (const auto& [name, value] : defines_)
    if (!usedDefines_.count(name)) unused.push_back(name);
  return unused;
}

}  // namespace lucent
