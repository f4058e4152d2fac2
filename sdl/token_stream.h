// The language core: POV-Ray's Scene Description Language evaluated as POV-Ray 3.7
// evaluates it, up to the scene items. Like POV-Ray, it works at the level of tokens: every
// directive (#declare, #if, #while, #macro, #include...) is done while the next token is
// read, a macro call continues reading in the macro's body, and a loop reads its body
// again. What comes out is the stream of tokens a scene reader sees (sphere, {, a number,
// an identifier and its value...), with the expressions it asks for evaluated here.
//
// POV-Ray 3.7's parser (tokenize.cpp, express.cpp, parse.cpp, parsestr.cpp) was read for
// the facts; the code here is Lucent's own.
#pragma once

#include "function.h"
#include "item_reader.h"
#include "keywords.h"
#include "options.h"
#include "source.h"
#include "spline.h"
#include "symbols.h"
#include "value.h"

#include "scenegraph/located_error.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lucent::sdl {

// An error in a POV-Ray scene: "file:line:col: error: message", followed by a
// "file:line:col: note: ..." line for each macro call and include that led there.
class SdlError : public LocatedError {
 public:
  using LocatedError::LocatedError;
};

enum class TokenKind {
  None,        // no token (a directive was done)
  End,         // the end of the scene
  Keyword,     // a reserved word; kw says what the core makes of it
  Identifier,  // a declared identifier; ref says where its value lives
  Undeclared,  // an identifier that names nothing
  MacroName,   // a macro's name where it is not called (after #declare, #undef...)
  Number,
  String,  // a string literal, escapes not yet done (stringValue() does them)
  Punct,
  Hash,  // a '#' read where no directive may start
};

struct Token {
  TokenKind kind = TokenKind::None;
  Kw kw = Kw::None;
  const RawToken* raw = nullptr;
  SourceFile* file = nullptr;
  Ref ref;               // Identifier
  int table = -1;        // Identifier, MacroName: the symbol table that holds it
  bool element = false;  // Identifier: an array element named by subscripts
  bool call = false;     // Identifier of a function followed by '(': a call, not the function
  std::shared_ptr<Macro> macro;

  std::string_view text() const { return raw ? raw->text : ""; }
  double number() const { return raw ? raw->number : 0; }
  SourceLoc loc() const { return file && raw ? file->loc(*raw) : SourceLoc{}; }
  bool is(std::string_view punct) const { return kind == TokenKind::Punct && text() == punct; }
  const Value* value() const { return ref.get(); }
  // How the token is named in messages: "'sphere'", "float identifier 'A'", "'{'"...
  std::string describe() const;
};

// Whether `t` starts a float, vector or colour expression (POV-Ray's optional arguments:
// `hollow [on|off]`, a step after #for's bounds).
bool startsExpression(const Token& t);

class TokenStream {
 public:
  explicit TokenStream(Options options, ItemReader* items = nullptr);
  ~TokenStream();
  TokenStream(const TokenStream&) = delete;
  TokenStream& operator=(const TokenStream&) = delete;

  // Starts reading a scene file (the folder it lies in is searched first by #include).
  void openFile(const std::filesystem::path& path);
  // Starts reading `text` as the scene file `name` lying in `folder`.
  void openText(const std::string& name, std::string text, const std::filesystem::path& folder);

  // --- What the scene reader uses.
  // The next token, every directive done; End at the end of the scene (and again after).
  const Token& next();
  // The next token, left to be read again.
  const Token& peek();
  // The token next() returned last is returned again by the next call.
  void unget() { unget_ = true; }
  const Token& current() const { return cur_; }

  double parseFloat();                  // a float expression
  std::array<double, 3> parseVector();  // a vector expression; a float f becomes <f,f,f>
  // A colour: `rgb <...>`, `color red 1 green 0.5`, a colour identifier, an expression of
  // 3 to 5 components...; red, green, blue, filter, transmit.
  std::array<double, 5> parseColour();
  std::string parseString();  // a string expression
  Value parseExpression();    // a float, vector or colour expression, any size
  // `function [(params)] { body }`, the keyword `function` just read: a declaration's
  // (`declaration`: parameters, `internal(N)`, pigment, pattern, transform and spline
  // functions allowed; `name` is the identifier being declared, "" for none) or an
  // isosurface's (x, y, z only). Located errors inside the body.
  std::shared_ptr<const FunctionValue> parseFunction(bool declaration, const std::string& name);
  void expect(std::string_view punct);  // a punctuation token, or an error naming it
  bool allow(std::string_view punct);   // reads it if it comes next
  void parseComma();                    // POV-Ray's optional comma
  // A file a shape reads (a font, a height field's image), searched as #include searches
  // (the scene's folder, then the library folders) and under the same access rules, also
  // with its type's `extensions` added (".ttf", ".TTF"); an error at `at` when not found.
  std::filesystem::path findDataFile(const std::string& name, const SourceLoc& at,
                                     const std::vector<std::string>& extensions) const;

  [[noreturn]] void error(const Token& at, const std::string& message) const;
  // The error `error(at, message)` throws, made but not thrown: for an error kept for later
  // (a refused declaration's), as a throw costs far more than the message.
  SdlError errorAt(const SourceLoc& at, const std::string& message) const;
  [[noreturn]] void error(const SourceLoc& at, const std::string& message) const;
  void warning(const SourceLoc& at, const std::string& message);

  // Set by the scene reader when it reads global_settings { assumed_gamma g } (g 0: srgb):
  // srgb colours are refused before (POV-Ray 3.7), and encoded with it after.
  void setAssumedGamma(double gamma) {
    assumedGamma_ = gamma > 0.0 ? gamma : 1.0;
    srgbWorking_ = !(gamma > 0.0);
  }

  // --- For tests and the command: an identifier's value as the scene left it.
  const Value* lookup(const std::string& name) const;
  // The names of the global symbol table (#declare's), sorted.
  std::vector<std::string> globalNames() const;
  double languageVersion() const { return version_ / 100.0; }
  // The version POV-Ray's rendering follows (its EffectiveLanguageVersion): 3.62 until a
  // #version is read anywhere (a scene of none, including no standard include, is a
  // legacy scene: gamma off, 3.6's opacity and sky), then languageVersion().
  double effectiveLanguageVersion() const { return versionSet_ ? languageVersion() : 3.62; }

 private:
  enum class Cond {
    None,
    IfTrue,
    IfFalse,
    Else,
    Switch,
    CaseTrue,
    CaseFalse,
    SkipTilEnd,
    While,
    For,
    DeclaringMacro,
    InvokingMacro
  };
  struct CondEntry {
    Cond type = Cond::IfTrue;
    SourceLoc loc;  // the directive that opened it
    std::string directive;
    double switchValue = 0;
    bool caseOk = false;
    SourceFile* loopFile = nullptr;
    size_t loopPos = 0;
    std::string forName;
    double forEnd = 0, forStep = 0;
    std::shared_ptr<Macro> macro;
    std::uint64_t iterations = 0;  // #while, #for: the iterations done
    SourceFile* returnFile = nullptr;
    size_t returnPos = 0;
  };
  struct Level {
    SourceFile* file = nullptr;
    size_t pos = 0;
  };
  struct Note {
    SourceLoc loc;
    std::string text;
  };
  struct Express {
    double v[5] = {0, 0, 0, 0, 0};
  };
  // Counts the nesting of expressions, string functions and arrays, which recurse on the
  // C++ stack, and refuses more than a bound (so `((((...` cannot overflow the stack).
  class Nesting {
   public:
    explicit Nesting(TokenStream& s);
    ~Nesting() { --s_.nesting_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    TokenStream& s_;
  };

  // token_stream.cpp: reading tokens
  void getToken();
  bool readWord(const RawToken& r, SourceFile* f);
  void resolveArrayElement(Token& t);
  const RawToken& rawPeek();
  SourceFile* load(const std::filesystem::path& canonical, const std::string& name);
  void pushCond(Cond type, const std::string& directive);
  std::string withNotes(const std::string& first) const;
  void countToken();
  void countLoop(CondEntry& c);
  Token makeToken(TokenKind kind, const RawToken& r, SourceFile* f) const;

  // directives.cpp
  bool directive();
  void directiveKeyword(bool& again);
  void ifDirective(Kw kw);
  void elseDirective(Kw kw, Cond current);
  void switchDirective();
  void caseDirective(Cond current);
  void endDirective(Cond current, SourceFile* hashFile, size_t hashPos);
  void loopEnd(CondEntry& c);
  void whileDirective();
  void forDirective();
  bool forParams(std::string& name, double& end, double& step);
  void skipTokens(Cond type);
  void breakDirective();
  void undefDirective();
  void versionDirective();
  void messageDirective(Kw kw);
  bool ifdefParam();
  double condParam();
  void condParam2(double& a, double& b);

  // object_functions.cpp: trace(), inside(), min_extent() and max_extent()
  std::shared_ptr<const ObjectGeometry> objectArgument(const Token& function);
  std::array<double, 3> traceFunction();
  double insideFunction();
  std::array<double, 3> extentFunction(Kw kw);

  // file_io.cpp: #fopen, #fclose, #read and #write
  void fopenDirective();
  void fcloseDirective();
  void readDirective();
  void writeDirective();
  Token fileIdentifier(const char* directive);
  void declareAs(const Token& target, Value v, const SourceLoc& at);

  // macros.cpp: macros and includes
  void macroDefinition();
  void invokeMacro(std::shared_ptr<Macro> m, SourceLoc callLoc);
  void returnFromMacro();
  void openInclude(const SourceLoc& at);
  std::filesystem::path findInclude(const std::string& name, const SourceLoc& at,
                                    std::string& display, bool tryInc = true,
                                    const std::vector<std::string>* extensions = nullptr) const;
  void noticeSkip();
  const std::filesystem::path& canonicalFolder(const std::filesystem::path& folder) const;

  // declarations.cpp
  void declare(bool local, const SourceLoc& at);
  bool rvalue(Value& out, Ref* byRef, bool parameter, bool semicolon);
  bool rvalueNumeric(Value& out, Ref* byRef, bool parameter, bool semicolon);
  std::shared_ptr<ArrayValue> arrayDeclaration();
  void arrayInitialiser(ArrayValue& a, size_t dim, size_t base);
  void assignElement(ArrayValue& a, size_t index, Value v, const SourceLoc& at);
  void store(const Ref& target, Value v, const SourceLoc& at);
  void semicolon(bool force);

  // expressions.cpp
  void factor(Express& e, int& terms);
  void factorValue(Express& e, int& terms);
  void identifierFactor(Express& e, int& terms);
  void vectorLiteral(Express& e, int& terms);
  void componentAccess(Express& e, int& terms);
  void term(Express& e, int& terms);
  void sum(Express& e, int& terms);
  void relation(Express& e, int& terms);
  void logical(Express& e, int& terms);
  void express(Express& e, int& terms);
  int unknownVector(Express& e);
  double floatParam();
  void floatParam2(double& a, double& b);
  std::array<double, 3> vectorParam();
  void vectorParam2(std::array<double, 3>& a, std::array<double, 3>& b);
  std::array<double, 5> colour(bool expectFilterTransmit);
  bool colourKey(Kw kw, std::array<double, 5>& c, bool started);

  // function_parse.cpp: the function language, and calls of functions in expressions
  struct FnScope;
  FnNodePtr fnOr(FnScope& s);
  FnNodePtr fnAnd(FnScope& s);
  FnNodePtr fnCompare(FnScope& s);
  FnNodePtr fnSum(FnScope& s);
  FnNodePtr fnProduct(FnScope& s);
  FnNodePtr fnUnary(FnScope& s);
  FnNodePtr fnPrimary(FnScope& s);
  FnNodePtr fnName(FnScope& s);
  FnNodePtr fnBuiltin(FnScope& s);
  FnNodePtr fnUserCall(FnScope& s);
  std::vector<FnNodePtr> fnArguments(FnScope& s);
  void fnSkipBlock();
  void functionCall(Express& e, int& terms);

  // spline_parse.cpp: `spline { }` (the keyword just read) and S(T [, KIND]) in expressions
  std::shared_ptr<const Spline> splineBlock();
  void splineCall(Express& e, int& terms, const Spline& s, bool kindArgument);

  // builtins.cpp
  double floatFunction(Kw kw);
  double minMaxFunction(Kw kw);
  double bitwiseFunction(Kw kw);
  double selectFunction();
  double arrayFunction(Kw kw);
  double randomFunction(Kw kw);
  double floatValue(Kw kw);
  std::array<double, 3> vectorFunction(Kw kw);
  std::array<double, 3> vturbulenceFunction();
  [[noreturn]] void notEvaluated(const Token& t) const;

  // strings.cpp
  bool stringExpression(std::string& out, bool pathname, bool require);
  std::string stringFunction(Kw kw, bool pathname);
  std::string strFunction();
  std::string vstrFunction();
  std::string substrFunction();
  std::string datetimeFunction();
  std::string decodeEscapes(const std::string& raw, const Token& at);
  void checkLength(size_t n);

  Options options_;
  ItemReader* items_;
  Output* out_;
  std::vector<std::unique_ptr<SourceFile>> files_;
  std::map<std::filesystem::path, SourceFile*> byPath_;
  struct FoundFile {
    std::filesystem::path path;
    std::string display;
  };
  // findInclude's answers (includes and data files) and the canonical folders, kept for the files
  // looked for again (the files and folders do not change while a scene is read).
  mutable std::map<std::string, FoundFile> foundIncludes_;
  mutable std::map<std::filesystem::path, std::filesystem::path> canonicalFolders_;
  std::filesystem::path sceneFolder_;         // canonical
  std::filesystem::path sceneDisplayFolder_;  // as given, for the names in messages
  std::shared_ptr<Macro> pendingMacro_;       // the macro a #macro directive defines
  std::vector<Level> levels_;
  std::vector<SymbolTable> tables_;
  std::vector<CondEntry> conds_;
  std::vector<Note> notes_;
  Token cur_;
  bool unget_ = false;
  bool okToDeclare_ = true;
  bool skipping_ = false;
  bool lvalueOk_ = false;
  bool insideIfdef_ = false;
  bool insideMacroDefinition_ = false;
  int version_ = 370;
  bool versionSet_ = false;   // a #version has been read
  double assumedGamma_ = 0;   // 0: not set
  bool srgbWorking_ = false;  // assumed_gamma srgb: an srgb colour is kept as written
  std::uint64_t tokens_ = 0;
  SourceLoc directiveLoc_;  // the '#' of the directive being done
  int nesting_ = 0;         // expressions, strings and arrays within each other
  std::string declaring_;   // the identifier a #declare or #local is giving a value
  std::vector<std::uint32_t> random_;
  std::uint64_t bytesWritten_ = 0;  // by #write, all files together
};

}  // namespace lucent::sdl
