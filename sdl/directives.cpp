// The directives, done as their '#' is read: conditions and loops over a stack of open
// directives, as POV-Ray 3.7 keeps them. A condition that is false, and the body of a
// macro being defined, are skipped token by token (nested directives still counted), so
// that #else, #case and #end are found where POV-Ray finds them.
#include "token_stream.h"

#include <cmath>
#include <cstdio>

namespace lucent::sdl {

namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON: "true" is |x| > 1e-10

std::string directiveName(std::string_view word) { return "#" + std::string(word); }

}  // namespace

void TokenStream::noticeSkip() {
  // Tells skipTokens that the directive just done ended the skipping (POV-Ray hands a '#'
  // back for that).
  cur_.kind = TokenKind::Hash;
  unget_ = true;
}

// The '#' has been read (cur_). True when cur_ then holds a token to hand on.
bool TokenStream::directive() {
  SourceFile* hashFile = levels_.back().file;
  size_t hashPos = levels_.back().pos - 1;
  if (!conds_.empty() && conds_.back().type == Cond::InvokingMacro) {
    const auto& m = conds_.back().macro;
    if (m->file == hashFile && m->endHash == hashPos) {  // the #end of the macro's body
      returnFromMacro();
      conds_.pop_back();
      cur_ = Token{};
      return false;
    }
  }
  if (!okToDeclare_) return true;  // a '#' where no directive may start: handed on
  for (;;) {
    Cond current = conds_.empty() ? Cond::None : conds_.back().type;
    const SourceLoc hashLoc = cur_.loc();  // the '#' (again: the next directive's)
    getToken();
    directiveLoc_ = hashLoc;
    bool again = false;
    if (cur_.kind == TokenKind::Keyword && cur_.kw == Kw::k_end) {
      endDirective(current, hashFile, hashPos);
    } else if (cur_.kind == TokenKind::Keyword && cur_.kw == Kw::k_else) {
      elseDirective(cur_.kw, current);
    } else if (cur_.kind == TokenKind::Keyword && cur_.kw == Kw::k_elseif) {
      elseDirective(cur_.kw, current);
    } else if (cur_.kind == TokenKind::Keyword &&
               (cur_.kw == Kw::k_case || cur_.kw == Kw::k_range)) {
      caseDirective(current);
    } else if (cur_.kind == TokenKind::MacroName) {
      if (skipping_) unget_ = true;
      else invokeMacro(std::shared_ptr<Macro>(cur_.macro), cur_.loc());
    } else if (cur_.kind == TokenKind::Keyword) {
      directiveKeyword(again);
    } else {
      unget_ = true;  // not a directive: the token is handed on
    }
    if (!again) break;
  }
  if (unget_) {
    unget_ = false;
    return true;
  }
  cur_ = Token{};
  return false;
}

// The directives other than #end, #else, #elseif, #case and #range. `again` is set when
// another directive follows at once (after a #declare or #version with no ';').
void TokenStream::directiveKeyword(bool& again) {
  const Kw kw = cur_.kw;
  const SourceLoc at = directiveLoc_;
  switch (kw) {
    case Kw::k_if:
    case Kw::k_ifdef:
    case Kw::k_ifndef:
      ifDirective(kw);
      return;
    case Kw::k_while:
      whileDirective();
      return;
    case Kw::k_for:
      forDirective();
      return;
    case Kw::k_switch:
      switchDirective();
      return;
    case Kw::k_break:
      if (!skipping_) breakDirective();
      return;
    case Kw::k_macro:
      if (!skipping_) {
        if (insideMacroDefinition_) error(cur_, "cannot nest macro definitions");
        insideMacroDefinition_ = true;
        macroDefinition();
        insideMacroDefinition_ = false;
      } else {
        pendingMacro_.reset();
      }
      {
        CondEntry c;
        c.type = Cond::DeclaringMacro;
        c.loc = directiveLoc_;
        c.directive = "#macro";
        c.macro = pendingMacro_;
        pendingMacro_.reset();
        if (static_cast<int>(conds_.size()) >= options_.limits.conditionDepth)
          error(at, "too many nested conditionals or macros");
        conds_.push_back(std::move(c));
      }
      skipTokens(Cond::DeclaringMacro);
      return;
    default:
      break;
  }
  if (skipping_) {  // the other directives are nothing while skipping
    unget_ = true;
    return;
  }
  switch (kw) {
    case Kw::k_declare:
    case Kw::k_local:
      declare(kw == Kw::k_local, at);
      if (unget_ && cur_.kind == TokenKind::Hash) {
        unget_ = false;
        again = true;
      } else if (unget_ && cur_.kind == TokenKind::MacroName) {
        again = true;
      }
      return;
    case Kw::k_version:
      versionDirective();
      if (unget_ && cur_.kind == TokenKind::Hash) {
        unget_ = false;
        again = true;
      }
      return;
    case Kw::k_include:
      openInclude(at);
      return;
    case Kw::k_undef:
      undefDirective();
      return;
    case Kw::k_debug:
    case Kw::k_warning:
    case Kw::k_error:
    case Kw::k_render:
    case Kw::k_statistics:
      messageDirective(kw);
      return;
    case Kw::k_fopen:
      fopenDirective();
      return;
    case Kw::k_fclose:
      fcloseDirective();
      return;
    case Kw::k_read:
      readDirective();
      return;
    case Kw::k_write:
      writeDirective();
      return;
    default:
      unget_ = true;  // #default and the rest: handed on to the scene reader
      return;
  }
}

void TokenStream::ifDirective(Kw kw) {
  pushCond(Cond::IfTrue, directiveName(cur_.text()));
  if (skipping_) {
    conds_.back().type = Cond::SkipTilEnd;
    skipTokens(Cond::SkipTilEnd);
    return;
  }
  bool value;
  if (kw == Kw::k_if) value = std::fabs(condParam()) > kEpsilon;
  else value = ifdefParam() != (kw == Kw::k_ifndef);
  if (value) {
    conds_.back().type = Cond::IfTrue;
  } else {
    conds_.back().type = Cond::IfFalse;
    skipTokens(Cond::IfFalse);
  }
}

void TokenStream::whileDirective() {
  pushCond(Cond::While, "#while");
  if (skipping_) {
    conds_.back().type = Cond::SkipTilEnd;
    skipTokens(Cond::SkipTilEnd);
    return;
  }
  conds_.back().loopFile = levels_.back().file;
  conds_.back().loopPos = levels_.back().pos;
  if (std::fabs(condParam()) > kEpsilon) return;
  conds_.back().type = Cond::SkipTilEnd;
  skipTokens(Cond::SkipTilEnd);
}

void TokenStream::forDirective() {
  pushCond(Cond::For, "#for");
  if (skipping_) {
    conds_.back().type = Cond::SkipTilEnd;
    skipTokens(Cond::SkipTilEnd);
    return;
  }
  std::string name;
  double end = 0, step = 0;
  if (forParams(name, end, step)) {
    CondEntry& c = conds_.back();
    c.loopFile = levels_.back().file;
    c.loopPos = levels_.back().pos;
    c.forName = name;
    c.forEnd = end;
    c.forStep = step;
  } else {
    conds_.back().type = Cond::SkipTilEnd;
    skipTokens(Cond::SkipTilEnd);
  }
}

// `#for (I, start, end [, step])`: I becomes a float of the current symbol table.
bool TokenStream::forParams(std::string& name, double& end, double& step) {
  expect("(");
  bool prevOk = okToDeclare_;
  okToDeclare_ = false;
  lvalueOk_ = true;
  getToken();
  lvalueOk_ = false;
  okToDeclare_ = prevOk;
  if (cur_.element) error(cur_, "the #for loop variable must not be an array element");
  if (cur_.kind != TokenKind::Undeclared && cur_.kind != TokenKind::Identifier)
    error(cur_, "expected the #for loop variable, found " + cur_.describe());
  name = std::string(cur_.text());
  std::shared_ptr<Symbol> s;
  if (cur_.kind == TokenKind::Identifier && cur_.table == static_cast<int>(tables_.size()) - 1 &&
      cur_.ref.symbol) {
    s = cur_.ref.symbol;
  } else {
    s = std::make_shared<Symbol>();
    tables_.back()[name] = s;
  }
  parseComma();
  double start = parseFloat();
  s->kind = Symbol::Kind::Value;
  s->value = Value::number(start);
  parseComma();
  end = parseFloat();
  parseComma();
  step = 1;
  getToken();
  unget_ = true;
  if (startsExpression(cur_)) step = parseFloat();
  if (std::fabs(step) < kEpsilon) error(cur_, "the #for loop increment must be non-zero");
  expect(")");
  return (step > 0 && start < end + kEpsilon) || (step < 0 && start > end - kEpsilon);
}

void TokenStream::elseDirective(Kw kw, Cond current) {
  if (kw == Kw::k_else) {
    switch (current) {
      case Cond::IfTrue:
        conds_.back().type = Cond::SkipTilEnd;
        skipTokens(Cond::SkipTilEnd);
        return;
      case Cond::IfFalse:
        conds_.back().type = Cond::Else;
        noticeSkip();
        return;
      case Cond::CaseTrue:
      case Cond::SkipTilEnd:
        return;
      case Cond::CaseFalse:
        conds_.back().type = Cond::CaseTrue;
        if (skipping_) noticeSkip();
        return;
      default:
        error(directiveLoc_, "#else without a matching #if, #ifdef, #ifndef or #switch");
    }
  }
  switch (current) {
    case Cond::IfTrue:
      conds_.back().type = Cond::SkipTilEnd;
      skipTokens(Cond::SkipTilEnd);
      return;
    case Cond::IfFalse:
      if (std::fabs(condParam()) > kEpsilon) {
        conds_.back().type = Cond::IfTrue;
        noticeSkip();
      }
      return;
    case Cond::SkipTilEnd:
      return;
    default:
      error(directiveLoc_, "#elseif without a matching #if");
  }
}

void TokenStream::switchDirective() {
  pushCond(Cond::Switch, "#switch");
  if (skipping_) {
    conds_.back().type = Cond::SkipTilEnd;
    skipTokens(Cond::SkipTilEnd);
    return;
  }
  conds_.back().switchValue = condParam();
  conds_.back().caseOk = false;
  getToken();  // #case or #range, done as a directive that hands back its keyword
  if (cur_.kind != TokenKind::Keyword || (cur_.kw != Kw::k_case && cur_.kw != Kw::k_range) ||
      !conds_.back().caseOk)
    error(cur_, "#switch not followed by #case or #range (found " + cur_.describe() + ")");
  bool flag;
  double sw = conds_.back().switchValue;
  if (cur_.kw == Kw::k_case) {
    flag = std::fabs(condParam() - sw) < kEpsilon;
  } else {
    double lo, hi;
    condParam2(lo, hi);
    flag = sw >= lo && sw <= hi;
  }
  if (flag) {
    conds_.back().type = Cond::CaseTrue;
  } else {
    conds_.back().type = Cond::CaseFalse;
    skipTokens(Cond::CaseFalse);
  }
}

void TokenStream::caseDirective(Cond current) {
  switch (current) {
    case Cond::CaseTrue:
    case Cond::CaseFalse: {
      bool flag;
      double sw = conds_.back().switchValue;
      if (cur_.kw == Kw::k_case) {
        flag = std::fabs(condParam() - sw) < kEpsilon;
      } else {
        double lo, hi;
        condParam2(lo, hi);
        flag = sw >= lo && sw <= hi;
      }
      if (flag && current == Cond::CaseFalse) {
        conds_.back().type = Cond::CaseTrue;
        if (skipping_) noticeSkip();
      }
      return;
    }
    case Cond::Switch:
      conds_.back().caseOk = true;
      unget_ = true;
      return;
    case Cond::SkipTilEnd:
      return;
    default:
      error(directiveLoc_, "#" + std::string(cur_.text()) + " without a matching #switch");
  }
}

void TokenStream::endDirective(Cond current, SourceFile* hashFile, size_t hashPos) {
  switch (current) {
    case Cond::InvokingMacro:
      returnFromMacro();
      conds_.pop_back();
      return;
    case Cond::IfFalse:
    case Cond::IfTrue:
    case Cond::Else:
    case Cond::CaseTrue:
    case Cond::CaseFalse:
    case Cond::DeclaringMacro:
    case Cond::SkipTilEnd:
      if (current == Cond::IfFalse) noticeSkip();
      if (current == Cond::DeclaringMacro && conds_.back().macro) {
        conds_.back().macro->file = hashFile;
        conds_.back().macro->endHash = hashPos;
      }
      conds_.pop_back();
      if (skipping_) noticeSkip();
      return;
    case Cond::While:
    case Cond::For:
      loopEnd(conds_.back());
      return;
    default:
      error(directiveLoc_, "#end without an open #if, #while, #for, #switch or #macro");
  }
}

// The #end of a loop: back to its start, for another iteration or to skip to this #end.
void TokenStream::loopEnd(CondEntry& c) {
  const bool isWhile = c.type == Cond::While;
  if (c.loopFile != levels_.back().file)
    error(cur_, std::string(isWhile ? "#while" : "#for") +
                    " loop did not end in the file where it started");
  countLoop(c);
  levels_.back().pos = c.loopPos;
  if (isWhile) {
    if (std::fabs(condParam()) < kEpsilon) {
      conds_.back().type = Cond::SkipTilEnd;
      skipTokens(Cond::SkipTilEnd);
    }
    return;
  }
  std::shared_ptr<Symbol>* it = tables_.back().find(c.forName);
  if (!it || (*it)->kind != Symbol::Kind::Value || (*it)->value.type != ValueType::Float)
    error(c.loc, "the #for loop variable '" + c.forName +
                     "' must remain defined and numerical during the loop");
  double& v = (*it)->value.v[0];
  v += c.forStep;
  if ((c.forStep > 0 && v > c.forEnd + kEpsilon) || (c.forStep < 0 && v < c.forEnd - kEpsilon)) {
    conds_.back().type = Cond::SkipTilEnd;
    skipTokens(Cond::SkipTilEnd);
  }
}

void TokenStream::skipTokens(Cond type) {
  const size_t depth = conds_.size();
  const bool prev = skipping_;
  skipping_ = true;
  while (conds_.size() > depth || (conds_.size() == depth && conds_.back().type == type))
    getToken();
  skipping_ = prev;
  if (cur_.kind == TokenKind::Hash) {
    cur_ = Token{};
    unget_ = false;
  } else {
    unget_ = true;
  }
}

void TokenStream::breakDirective() {
  const SourceLoc at = directiveLoc_;
  const bool prev = skipping_;
  skipping_ = true;
  auto stops = [this] {
    Cond t = conds_.back().type;
    return t == Cond::While || t == Cond::For || t == Cond::CaseTrue || t == Cond::InvokingMacro;
  };
  while (!conds_.empty() && !stops()) getToken();
  if (conds_.empty()) error(at, "#break outside of a #while, #for, #switch or macro");
  if (conds_.back().type == Cond::InvokingMacro) {
    skipping_ = prev;
    returnFromMacro();
    conds_.pop_back();
    return;
  }
  conds_.back().type = Cond::SkipTilEnd;
  skipTokens(Cond::SkipTilEnd);
  skipping_ = prev;
}

void TokenStream::undefDirective() {
  okToDeclare_ = false;
  getToken();
  okToDeclare_ = true;
  if (cur_.kind == TokenKind::Undeclared) {
    warning(cur_.loc(), "attempt to #undef unknown identifier '" + std::string(cur_.text()) + "'");
    return;
  }
  if (cur_.kind != TokenKind::Identifier && cur_.kind != TokenKind::MacroName)
    error(cur_, "expected an identifier after #undef, found " + cur_.describe());
  if (cur_.element) cur_.ref.array->elements[cur_.ref.index].reset();
  else tables_[cur_.table].erase(cur_.text());
}

void TokenStream::versionDirective() {
  okToDeclare_ = false;
  getToken();
  if (!(cur_.kind == TokenKind::Undeclared && cur_.text() == "unofficial")) unget_ = true;
  const SourceLoc at = cur_.loc();
  version_ = static_cast<int>(parseFloat() * 100 + 0.5);
  versionSet_ = true;
  semicolon(false);
  if (version_ > 370) {
    char v[32];
    std::snprintf(v, sizeof v, "%g", version_ / 100.0);
    error(at, std::string("this scene requires POV-Ray version ") + v +
                  " or later (Lucent reads POV-Ray 3.7)");
  }
  okToDeclare_ = true;
}

void TokenStream::messageDirective(Kw kw) {
  const SourceLoc at = directiveLoc_;
  if (kw == Kw::k_render || kw == Kw::k_statistics)
    warning(at,
            "#render and #statistics streams are no longer available; redirecting "
            "output to the #debug stream");
  std::string s;
  stringExpression(s, false, true);
  if (kw == Kw::k_warning || kw == Kw::k_error) {
    if (s.size() > 160) s = s.substr(0, 124) + "...";  // as POV-Ray shortens them
    if (kw == Kw::k_warning) warning(at, s);
    if (kw == Kw::k_error) error(at, "parse halted by #error directive: " + s);
    return;
  }
  if (s.size() > 200) s = s.substr(0, 156) + "...";
  out_->debug(s);
}

// `defined(X)`, `#ifdef (X)`: X names a value or macro; an array element, one given a value.
bool TokenStream::ifdefParam() {
  expect("(");
  insideIfdef_ = true;
  getToken();
  insideIfdef_ = false;
  const std::string name(cur_.text());
  bool result = false;
  for (auto t = tables_.rbegin(); t != tables_.rend(); ++t) {
    std::shared_ptr<Symbol>* it = t->find(name);
    if (!it) continue;
    result = true;
    const Symbol& s = **it;
    Ref r = s.kind == Symbol::Kind::Parameter ? s.target : Ref{*it, nullptr, 0};
    const Value* v = s.kind == Symbol::Kind::Macro ? nullptr : r.get();
    if (v && v->type == ValueType::Array && rawPeek().kind == RawKind::Punct &&
        rawPeek().text == "[") {
      Token t2 = cur_;
      t2.ref = r;
      bool prev = lvalueOk_;
      lvalueOk_ = true;
      resolveArrayElement(t2);
      lvalueOk_ = prev;
      result = t2.value() != nullptr;
    }
    break;
  }
  expect(")");
  return result;
}

double TokenStream::condParam() {
  bool ok = okToDeclare_, sk = skipping_;
  okToDeclare_ = false;
  skipping_ = false;
  double v = floatParam();
  okToDeclare_ = ok;
  skipping_ = sk;
  return v;
}

void TokenStream::condParam2(double& a, double& b) {
  bool ok = okToDeclare_, sk = skipping_;
  okToDeclare_ = false;
  skipping_ = false;
  floatParam2(a, b);
  okToDeclare_ = ok;
  skipping_ = sk;
}

}  // namespace lucent::sdl
