// #fopen, #fclose, #read and #write, as POV-Ray 3.7 does them (docs/povray-import.md,
// "File input and output"). A file is read whole when opened, found as an include file is
// (the scene's folder, then the library folders, within the file-access rules); #read takes
// the next comma-separated values (floats, vectors <...>, strings "...") and, once only
// blanks and commas are left, closes the file and undefines its identifier, as POV-Ray does
// (a `#while (defined(F))` loop reads to the end). Writing is refused unless the file lies in
// a folder of Options::writeFolders (--allow-write), and bounded in bytes.
#include "token_stream.h"

#include "lang/file_access.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace lucent::sdl {

namespace fs = std::filesystem;

namespace {

// An open file, shared by the identifier's copies (the Item itself stays const).
struct OpenFile {
  std::string display;  // as messages name it
  bool writing = false;
  std::string text;  // reading: the whole file
  size_t pos = 0;
  int line = 1, col = 1;
  std::ofstream out;  // writing
};

struct FileItem : Item {
  std::shared_ptr<OpenFile> file;
  std::string_view kind() const override { return "file"; }
};

OpenFile* openFileOf(const Token& t) {
  const Value* v = t.kind == TokenKind::Identifier ? t.value() : nullptr;
  if (!v || v->type != ValueType::Item) return nullptr;
  const auto* item = dynamic_cast<const FileItem*>(v->item.get());
  return item ? item->file.get() : nullptr;
}

// The reading side: blanks, commas and the values between them.
class DataReader {
 public:
  explicit DataReader(OpenFile& f) : f_(f) {}

  // Skips blanks and commas; false at the end of the file.
  bool more() {
    while (f_.pos < f_.text.size()) {
      const char c = f_.text[f_.pos];
      if (c != ',' && !std::isspace(static_cast<unsigned char>(c))) return true;
      advance();
    }
    return false;
  }

  // The value that starts here; `problem` set (and a float 0 returned) when there is none.
  Value value(std::string& problem, SourceLoc& at) {
    at = SourceLoc{f_.display, f_.line, f_.col};
    const char c = f_.text[f_.pos];
    if (c == '"') {
      advance();
      std::string s;
      while (f_.pos < f_.text.size() && f_.text[f_.pos] != '"') s += advance();
      if (f_.pos >= f_.text.size()) {
        problem = "the string has no closing quote";
        return Value{};
      }
      advance();
      return Value::string(std::move(s));
    }
    if (c == '<') {
      advance();
      double e[5] = {0, 0, 0, 0, 0};
      int n = 0;
      for (;;) {
        skipBlanks();
        if (f_.pos < f_.text.size() && f_.text[f_.pos] == '>') break;
        if (n == 5 || !number(e[n])) {
          problem = n == 5 ? "a vector of more than 5 components" : "a number was expected";
          return Value{};
        }
        ++n;
        skipBlanks();
        if (f_.pos < f_.text.size() && f_.text[f_.pos] == ',') advance();
      }
      advance();
      if (n < 2) {
        problem = "a vector needs 2 to 5 components";
        return Value{};
      }
      return Value::numeric(e, n);
    }
    double v = 0;
    if (!number(v)) {
      problem = std::string("unexpected '") + c + "' (a float, <vector> or \"string\" expected)";
      return Value{};
    }
    return Value::number(v);
  }

 private:
  char advance() {
    const char c = f_.text[f_.pos++];
    if (c == '\n') {
      ++f_.line;
      f_.col = 1;
    } else {
      ++f_.col;
    }
    return c;
  }
  void skipBlanks() {
    while (f_.pos < f_.text.size() && std::isspace(static_cast<unsigned char>(f_.text[f_.pos])))
      advance();
  }
  bool number(double& v) {
    const char* start = f_.text.c_str() + f_.pos;
    char* end = nullptr;
    v = std::strtod(start, &end);
    if (end == start) return false;
    for (const char* p = start; p < end; ++p) advance();
    return true;
  }

  OpenFile& f_;
};

// POV-Ray writes floats as printf's %g, and vectors as <a,b,c> with a blank after them.
std::string written(const Value& v) {
  char buf[40];
  auto g = [&](double x) {
    std::snprintf(buf, sizeof buf, "%g", x);
    return std::string(buf);
  };
  if (v.type == ValueType::Float) return g(v.v[0]);
  std::string s = "<";
  for (int i = 0; i < v.terms(); ++i) s += (i ? "," : "") + g(v.v[static_cast<size_t>(i)]);
  return s + "> ";
}

bool startsString(const Token& t) {
  if (t.kind == TokenKind::String) return true;
  if (t.kind == TokenKind::Keyword && isStringFunction(t.kw)) return true;
  const Value* v = t.kind == TokenKind::Identifier ? t.value() : nullptr;
  return v && v->type == ValueType::String;
}

}  // namespace

// Declares `target` (an identifier as read with lvalueOk_) as #declare does.
void TokenStream::declareAs(const Token& target, Value v, const SourceLoc& at) {
  if (target.kind == TokenKind::Undeclared) {
    auto s = std::make_shared<Symbol>();
    s->value = std::move(v);
    tables_[0][target.text()] = s;
  } else if (target.kind == TokenKind::Identifier) {
    store(target.ref, std::move(v), at);
  } else {
    error(target, "expected an identifier, found " + target.describe());
  }
}

// The file identifier a directive names (the '(' already read for #read and #write).
Token TokenStream::fileIdentifier(const char* directive) {
  getToken();
  if (!openFileOf(cur_))
    error(cur_, std::string("expected a file identifier (opened by #fopen) in ") + directive +
                    ", found " + cur_.describe());
  return cur_;
}

void TokenStream::fopenDirective() {
  const SourceLoc at = directiveLoc_;
  okToDeclare_ = false;
  lvalueOk_ = true;
  getToken();
  lvalueOk_ = false;
  const Token target = cur_;
  if (target.kind != TokenKind::Undeclared && target.kind != TokenKind::Identifier)
    error(target, "expected an identifier for the file after #fopen, found " + target.describe());
  std::string name;
  stringExpression(name, true, true);
  getToken();
  const std::string mode(cur_.kind == TokenKind::Keyword ? cur_.text() : "");
  if (mode != "read" && mode != "write" && mode != "append")
    error(cur_,
          "expected read, write or append after #fopen's file name, found " + cur_.describe());
  auto file = std::make_shared<OpenFile>();
  if (mode == "read") {
    // Found where #include would find it, within the same rules.
    bool exists = false;
    std::vector<fs::path> folders{sceneFolder_};
    folders.insert(folders.end(), options_.includeFolders.begin(), options_.includeFolders.end());
    for (const fs::path& folder : folders) {
      std::error_code ec;
      exists = exists || fs::is_regular_file(
                             fs::path(name).is_absolute() ? fs::path(name) : folder / name, ec);
    }
    if (!exists)
      error(at, "#fopen: no file '" + name +
                    "' to read (searched the scene's folder and the library folders)");
    const fs::path path = findInclude(name, at, file->display);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) error(at, "#fopen: cannot read '" + name + "'");
    file->text = text.str();
    if (file->text.size() > options_.limits.fileBytes)
      error(at, "#fopen: '" + name + "' holds more than " +
                    std::to_string(options_.limits.fileBytes) + " bytes (the limit of data files)");
  } else {
    const fs::path path =
        canonicalPath(fs::path(name).is_absolute() ? fs::path(name) : sceneFolder_ / name);
    bool allowed = false;
    for (const fs::path& folder : options_.writeFolders) {
      const fs::path rel = path.lexically_relative(canonicalPath(folder));
      allowed = allowed || (!rel.empty() && *rel.begin() != "..");
    }
    if (!allowed)
      error(at, "#fopen " + std::string(target.text()) + " \"" + name + "\" " + mode +
                    ": writing files is refused unless --allow-write names a folder that holds "
                    "it (" +
                    path.string() + ")");
    file->writing = true;
    file->display = path.string();
    foundIncludes_.clear();  // a file written may be included next, found anew
    file->out.open(path, mode == "append" ? std::ios::binary | std::ios::app
                                          : std::ios::binary | std::ios::trunc);
    if (!file->out) error(at, "#fopen: cannot open '" + path.string() + "' for writing");
  }
  Value v;
  v.type = ValueType::Item;
  auto item = std::make_shared<FileItem>();
  item->file = file;
  v.item = item;
  declareAs(target, std::move(v), at);
  okToDeclare_ = true;
}

void TokenStream::fcloseDirective() {
  okToDeclare_ = false;
  getToken();
  okToDeclare_ = true;
  // A file #read to its end is already closed and undefined: nothing to do, as in POV-Ray.
  if (cur_.kind == TokenKind::Undeclared) return;
  OpenFile* f = openFileOf(cur_);
  if (!f) error(cur_, "expected a file identifier after #fclose, found " + cur_.describe());
  if (f->writing) f->out.close();
  tables_[cur_.table].erase(cur_.text());
}

void TokenStream::readDirective() {
  const SourceLoc at = directiveLoc_;
  okToDeclare_ = false;
  expect("(");
  const Token id = fileIdentifier("#read");
  OpenFile& f = *openFileOf(id);
  if (f.writing) error(id, "#read: '" + std::string(id.text()) + "' was opened for writing");
  DataReader data(f);
  for (;;) {
    getToken();
    if (cur_.is(")")) break;
    if (!cur_.is(",")) error(cur_, "expected ',' or ')' in #read, found " + cur_.describe());
    lvalueOk_ = true;
    getToken();
    lvalueOk_ = false;
    const Token target = cur_;
    if (!data.more()) continue;  // past the end: the identifier keeps its value
    std::string problem;
    SourceLoc where;
    Value v = data.value(problem, where);
    if (!problem.empty()) error(where, "#read: " + problem);
    declareAs(target, std::move(v), at);
  }
  // Nothing left but blanks and commas: POV-Ray closes the file and undefines it.
  if (!data.more()) tables_[id.table].erase(id.text());
  okToDeclare_ = true;
}

void TokenStream::writeDirective() {
  okToDeclare_ = false;
  expect("(");
  const Token id = fileIdentifier("#write");
  OpenFile& f = *openFileOf(id);
  if (!f.writing) error(id, "#write: '" + std::string(id.text()) + "' was opened for reading");
  std::string out;
  for (;;) {
    parseComma();
    getToken();
    if (cur_.is(")")) break;
    const Token first = cur_;
    unget_ = true;
    if (startsString(first)) {
      std::string s;
      stringExpression(s, false, true);
      out += s;
    } else if (startsExpression(first)) {
      out += written(parseExpression());
    } else {
      error(first,
            "#write: expected a string or a float or vector expression, found " + first.describe());
    }
    if (bytesWritten_ + out.size() > options_.limits.fileBytes)
      error(first, "#write: more than " + std::to_string(options_.limits.fileBytes) +
                       " bytes written (the limit of what a scene may write)");
  }
  bytesWritten_ += out.size();
  f.out << out;
  if (!f.out) error(id, "#write: cannot write to '" + f.display + "'");
  okToDeclare_ = true;
}

}  // namespace lucent::sdl
