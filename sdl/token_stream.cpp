// Reading tokens: the files, the input levels (the scene, then each include being read),
// identifiers looked up in the symbol tables, and the errors with their context.
#include "token_stream.h"

#include "console_text.h"

#include "lang/file_access.h"
#include "lang/source_file.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace lucent::sdl {

namespace {

// #debug and warnings on the standard error stream when the caller gave no Output.
class ConsoleOutput : public Output {
 public:
  void debug(const std::string& text) override { std::cerr << printer_.add(text) << std::flush; }
  void warning(const SourceLoc& loc, const std::string& message) override {
    std::cerr << loc.str() << ": warning: " << message << "\n";
  }

 private:
  DebugPrinter printer_;  // as POV-Ray prints it
};

// Deep enough for any scene, shallow enough for the C++ stack.
constexpr int kMaxNesting = 1000;

ConsoleOutput& consoleOutput() {
  static ConsoleOutput c;
  return c;
}

}  // namespace

const Value* Ref::get() const {
  if (array) {
    const auto& e = array->elements[index];
    return e ? &*e : nullptr;
  }
  return symbol ? &symbol->value : nullptr;
}

void Ref::set(Value v) const {
  if (array) {
    array->elements[index] = std::move(v);
  } else if (symbol) {
    symbol->kind = Symbol::Kind::Value;
    symbol->value = std::move(v);
  }
}

std::string Token::describe() const {
  switch (kind) {
    case TokenKind::None:
      return "nothing";
    case TokenKind::End:
      return "the end of the file";
    case TokenKind::Keyword:
      return "'" + std::string(text()) + "'";
    case TokenKind::Identifier: {
      const Value* v = value();
      return (v ? typeName(*v) : std::string("array element")) + " '" + std::string(text()) + "'";
    }
    case TokenKind::Undeclared:
      return "undeclared identifier '" + std::string(text()) + "'";
    case TokenKind::MacroName:
      return "macro identifier '" + std::string(text()) + "'";
    case TokenKind::Number:
      return "float constant";
    case TokenKind::String:
      return "string literal";
    case TokenKind::Punct:
      return "'" + std::string(text()) + "'";
    case TokenKind::Hash:
      return "'#'";
  }
  return "token";
}

TokenStream::TokenStream(Options options, ItemReader* items)
    : options_(std::move(options)), items_(items) {
  out_ = options_.output ? options_.output : &consoleOutput();
  tables_.emplace_back();
  auto declareFloat = [this](const std::string& name, double v) {
    auto s = std::make_shared<Symbol>();
    s->value = Value::number(v);
    tables_[0][name] = s;
  };
  const Options& o = options_;
  declareFloat("clock_delta", o.clockDelta);
  declareFloat("initial_clock", o.initialClock);
  declareFloat("final_clock", o.finalClock);
  declareFloat("frame_number", o.frameNumber);
  declareFloat("initial_frame", o.initialFrame);
  declareFloat("final_frame", o.finalFrame);
  declareFloat("image_width", o.imageWidth);
  declareFloat("image_height", o.imageHeight);
  for (const auto& [name, v] : o.declared) declareFloat(name, v);
}

TokenStream::~TokenStream() = default;

SourceFile* TokenStream::load(const std::filesystem::path& canonical, const std::string& name) {
  auto it = byPath_.find(canonical);
  if (it != byPath_.end()) return it->second;
  std::string text;
  if (auto problem = readSceneText(canonical, text))
    throw SdlError(SourceLoc{name, 0, 0}, *problem, LocatedError::Kind::Input);
  files_.push_back(std::make_unique<SourceFile>(name, canonical.parent_path(), std::move(text)));
  byPath_[canonical] = files_.back().get();
  return files_.back().get();
}

void TokenStream::openFile(const std::filesystem::path& path) {
  std::filesystem::path c = canonicalPath(path);
  sceneFolder_ = c.parent_path();
  sceneDisplayFolder_ = path.parent_path();
  levels_.push_back({load(c, path.string()), 0});
}

void TokenStream::openText(const std::string& name, std::string text,
                           const std::filesystem::path& folder) {
  sceneFolder_ = canonicalPath(folder);
  sceneDisplayFolder_.clear();  // includes beside the text are named as written
  files_.push_back(std::make_unique<SourceFile>(name, sceneFolder_, std::move(text)));
  levels_.push_back({files_.back().get(), 0});
}

std::string TokenStream::withNotes(const std::string& first) const {
  std::string m = first;
  for (auto it = notes_.rbegin(); it != notes_.rend(); ++it)
    m += "\n" + it->loc.str() + ": note: " + it->text;
  return m;
}

SdlError TokenStream::errorAt(const SourceLoc& at, const std::string& message) const {
  return SdlError(at, withNotes(message));
}

void TokenStream::error(const SourceLoc& at, const std::string& message) const {
  throw errorAt(at, message);
}

void TokenStream::error(const Token& at, const std::string& message) const {
  if (at.raw) error(at.loc(), message);
  if (!levels_.empty()) {
    const Level& l = levels_.back();
    error(l.file->loc(l.file->at(l.pos > 0 ? l.pos - 1 : 0)), message);
  }
  error(SourceLoc{}, message);
}

void TokenStream::warning(const SourceLoc& at, const std::string& message) {
  out_->warning(at, message);
}

Token TokenStream::makeToken(TokenKind kind, const RawToken& r, SourceFile* f) const {
  Token t;
  t.kind = kind;
  t.raw = &r;
  t.file = f;
  return t;
}

void TokenStream::countToken() {
  if (++tokens_ <= options_.limits.tokens) return;
  const Level& l = levels_.back();
  error(l.file->loc(l.file->at(l.pos - 1)),
        "the scene reads more than " + std::to_string(options_.limits.tokens) +
            " tokens (the limit of an evaluation, which --pov-max-tokens raises; see "
            "docs/povray-import.md)");
}

void TokenStream::countLoop(CondEntry& c) {
  if (++c.iterations <= options_.limits.loopIterations) return;
  error(c.loc, "this " + c.directive + " loop ran more than " +
                   std::to_string(options_.limits.loopIterations) +
                   " times (the limit of one loop; see docs/povray-import.md)");
}

const RawToken& TokenStream::rawPeek() {
  Level& l = levels_.back();
  try {
    return l.file->at(l.pos);
  } catch (const LexError& e) {
    error(SourceLoc{l.file->name(), e.line, e.col}, e.message);
  }
}

void TokenStream::getToken() {
  if (unget_) {
    unget_ = false;
    return;
  }
  for (;;) {
    if (levels_.empty()) {
      cur_ = Token{};
      cur_.kind = TokenKind::End;
      return;
    }
    Level& l = levels_.back();
    SourceFile* f = l.file;
    const RawToken& r = rawPeek();
    if (r.kind == RawKind::End) {
      if (levels_.size() > 1) {  // the end of an include file: back to the file that named it
        levels_.pop_back();
        tables_.pop_back();
        notes_.pop_back();
        continue;
      }
      if (!conds_.empty())
        error(conds_.back().loc,
              "this " + conds_.back().directive + " has no #end before the end of the file");
      cur_ = makeToken(TokenKind::End, r, f);
      return;
    }
    ++l.pos;
    countToken();
    switch (r.kind) {
      case RawKind::Punct:
        if (r.text == "#") {
          cur_ = makeToken(TokenKind::Hash, r, f);
          if (directive()) return;
          continue;
        }
        cur_ = makeToken(TokenKind::Punct, r, f);
        return;
      case RawKind::Word:
        if (readWord(r, f)) return;
        continue;
      case RawKind::Number:
        cur_ = makeToken(TokenKind::Number, r, f);
        return;
      default:
        cur_ = makeToken(TokenKind::String, r, f);
        return;
    }
  }
}

// An identifier or reserved word. A macro's name calls the macro where a directive may
// start (the tokens that follow come from its body): false then, as no token was made.
bool TokenStream::readWord(const RawToken& r, SourceFile* f) {
  if (r.keyword >= 0 && !insideIfdef_) {
    cur_ = makeToken(TokenKind::Keyword, r, f);
    cur_.kw = keywordKind(r.keyword);
    return true;
  }
  if (insideIfdef_ || skipping_) {
    cur_ = makeToken(TokenKind::Undeclared, r, f);
    return true;
  }
  for (int i = static_cast<int>(tables_.size()) - 1; i >= 0; --i) {
    std::shared_ptr<Symbol>* it = tables_[i].find(r.text);
    if (!it) continue;
    const Symbol& s = **it;
    if (s.kind == Symbol::Kind::Macro) {
      if (okToDeclare_) {
        invokeMacro(std::shared_ptr<Macro>(s.macro), f->loc(r));
        return false;
      }
      cur_ = makeToken(TokenKind::MacroName, r, f);
      cur_.macro = s.macro;
      cur_.table = i;
      return true;
    }
    Token t = makeToken(TokenKind::Identifier, r, f);
    t.table = i;
    t.ref = s.kind == Symbol::Kind::Parameter ? s.target : Ref{*it, nullptr, 0};
    const Value* v = t.ref.get();
    if (v && v->type == ValueType::Array && rawPeek().kind == RawKind::Punct &&
        rawPeek().text == "[")
      resolveArrayElement(t);
    const Value* named = t.ref.get();  // the element, for an array's
    if (named && (named->type == ValueType::Function || named->type == ValueType::Spline))
      t.call = rawPeek().kind == RawKind::Punct && rawPeek().text == "(";
    cur_ = t;
    return true;
  }
  cur_ = makeToken(TokenKind::Undeclared, r, f);
  return true;
}

// `A[i][j]`: the element, with every dimension given (POV-Ray: a subscript rounds down
// after adding 1e-10).
void TokenStream::resolveArrayElement(Token& t) {
  std::shared_ptr<ArrayValue> a = t.ref.get()->array;
  bool lvalue = lvalueOk_;
  size_t index = 0;
  for (size_t d = 0; d < a->sizes.size(); ++d) {
    expect("[");
    const Token open = cur_;
    double val = parseFloat();
    if (!(val > -1e15 && val < 1e15)) val = -1;  // NaN or absurd: refused below
    long long k = static_cast<long long>(val + 1e-10);
    if (k < 0 || val < -1e-10) error(open, "negative array subscript");
    if (k >= a->sizes[d])
      error(open, "array subscript " + std::to_string(k) + " out of range (dimension " +
                      std::to_string(d + 1) + " has " + std::to_string(a->sizes[d]) + " elements)");
    index += static_cast<size_t>(k) * a->strides[d];
    expect("]");
  }
  t.ref = Ref{nullptr, a, index};
  t.element = true;
  if (!lvalue && !a->elements[index])
    error(t, "'" + std::string(t.text()) + "': attempt to access an uninitialized array element");
}

TokenStream::Nesting::Nesting(TokenStream& s) : s_(s) {
  if (++s_.nesting_ > kMaxNesting)
    s_.error(s_.cur_, "expressions, strings or arrays nested more than " +
                          std::to_string(kMaxNesting) + " deep");
}

void TokenStream::pushCond(Cond type, const std::string& directive) {
  if (static_cast<int>(conds_.size()) >= options_.limits.conditionDepth)
    error(cur_, "too many nested conditionals or macros (the limit is " +
                    std::to_string(options_.limits.conditionDepth) + ")");
  CondEntry c;
  c.type = type;
  c.loc = directiveLoc_;
  c.directive = directive;
  conds_.push_back(std::move(c));
}

const Token& TokenStream::next() {
  getToken();
  return cur_;
}

const Token& TokenStream::peek() {
  getToken();
  unget_ = true;
  return cur_;
}

void TokenStream::expect(std::string_view punct) {
  getToken();
  if (!cur_.is(punct))
    error(cur_, "expected '" + std::string(punct) + "', found " + cur_.describe());
}

bool TokenStream::allow(std::string_view punct) {
  getToken();
  if (cur_.is(punct)) return true;
  unget_ = true;
  return false;
}

void TokenStream::parseComma() { allow(","); }

const Value* TokenStream::lookup(const std::string& name) const {
  for (auto t = tables_.rbegin(); t != tables_.rend(); ++t) {
    const std::shared_ptr<Symbol>* it = t->find(name);
    if (!it) continue;
    if ((*it)->kind == Symbol::Kind::Parameter) return (*it)->target.get();
    if ((*it)->kind == Symbol::Kind::Macro) return nullptr;
    return &(*it)->value;
  }
  return nullptr;
}

std::vector<std::string> TokenStream::globalNames() const {
  std::vector<std::string> names;
  for (std::string_view n : tables_.front().names()) names.emplace_back(n);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace lucent::sdl
