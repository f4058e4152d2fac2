#include "parameters.h"

#include "did_you_mean.h"

namespace lucent {

namespace {
bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }
}  // namespace

Parameters::Parameters(const std::map<std::string, std::string>& defines, Diagnostics& diags)
    : defines_(defines), diags_(diags) {}

bool Parameters::isValidName(std::string_view name) {
  if (name.empty() || !isNameStart(name[0])) return false;
  for (char c : name)
    if (!isNameChar(c)) return false;
  return true;
}

void Parameters::declare(const std::string& name, const std::string& rawValue, const SourceLoc& loc,
                         const SourceLoc& valueLoc) {
  auto [it, inserted] = params_.try_emplace(name);
  if (!inserted) {
    diags_.error(loc, "<param> '" + name + "' is already declared (first declared at " +
                          it->second.loc.str() + ")");
    return;
  }
  it->second.raw = rawValue;
  it->second.loc = loc;
  it->second.valueLoc = valueLoc;
  order_.push_back(name);
}

std::vector<std::string> Parameters::knownNames() const {
  std::vector<std::string> names = order_;
  for (const auto& [name, value] : defines_)
    if (!params_.count(name)) names.push_back(name);
  return names;
}

std::optional<std::string> Parameters::lookup(const std::string& name, std::string& error) {
  auto it = params_.find(name);
  if (it != params_.end()) it->second.used = true;
  if (auto d = defines_.find(name); d != defines_.end()) {
    usedDefines_.insert(name);
    return d->second;  // -D wins, taken literally
  }
  if (it == params_.end()) {
    error = "undefined parameter '" + name + "'" + didYouMean(name, knownNames()) +
            "; declare it with <param name=\"" + name + "\" value=\"...\"/> or -D " + name + "=...";
    return std::nullopt;
  }
  Param& p = it->second;
  switch (p.state) {
    case State::Resolved: return p.value;
    case State::Failed: return std::nullopt;  // already reported at the <param>
    case State::Resolving: {
      std::string chain;
      for (const std::string& n : resolving_) chain += n + " -> ";
      diags_.error(p.loc, "<param> '" + name + "' refers to itself: " + chain + name);
      p.state = State::Failed;
      return std::nullopt;
    }
    case State::Unresolved: break;
  }
  p.state = State::Resolving;
  resolving_.push_back(name);
  std::string inner;
  std::optional<std::string> value = substitute(p.raw, inner);
  resolving_.pop_back();
  Param& q = p;  // references into an unordered_map survive rehashing
  if (!value) {
    if (!inner.empty()) diags_.error(q.valueLoc, "<param> '" + name + "' attribute 'value': " + inner);
    q.state = State::Failed;
    return std::nullopt;
  }
  if (q.state == State::Failed) return std::nullopt;  // a cycle through it was reported
  q.state = State::Resolved;
  q.value = *value;
  return q.value;
}

std::optional<std::string> Parameters::substitute(std::string_view text, std::string& error) {
  if (text.find('$') == std::string_view::npos) return std::string(text);
  std::string out;
  out.reserve(text.size());
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
    std::string name;
    if (i + 1 < text.size() && text[i + 1] == '{') {
      size_t close = text.find('}', i + 2);
      if (close == std::string_view::npos) {
        error = "'${' without a closing '}'";
        return std::nullopt;
      }
      name = std::string(text.substr(i + 2, close - i - 2));
      if (!isValidName(name)) {
        error = "'${" + name + "}' is not a parameter name (letters, digits and '_')";
        return std::nullopt;
      }
      i = close + 1;
    } else {
      size_t j = i + 1;
      while (j < text.size() && isNameChar(text[j])) ++j;
      name = std::string(text.substr(i + 1, j - i - 1));
      if (!isValidName(name)) {
        error = "'$' must be followed by a parameter name or {name} (write $$ for a literal '$')";
        return std::nullopt;
      }
      i = j;
    }
    std::optional<std::string> value = lookup(name, error);
    if (!value) return std::nullopt;
    out += *value;
  }
  return out;
}

std::vector<std::string> Parameters::unusedDefines() const {
  std::vector<std::string> unused;
  for (const auto& [name, value] : defines_)
    if (!usedDefines_.count(name)) unused.push_back(name);
  return unused;
}

}  // namespace lucent
