// Macros and include files: both continue reading elsewhere (the macro's body, the
// included file) with a new symbol table for their #local identifiers, and come back.
#include "token_stream.h"

#include "lang/file_access.h"

#include <algorithm>

namespace lucent::sdl {

namespace {

// POV-Ray 3.7 refuses a macro's 56th parameter.
constexpr size_t kMaxParameters = 55;

}  // namespace

// `#macro Name(A, B, ...)`: the body is skipped now (directives.cpp) and read at each call.
void TokenStream::macroDefinition() {
  const bool prevOk = okToDeclare_;
  okToDeclare_ = false;
  getToken();
  if (cur_.kind != TokenKind::Undeclared && cur_.kind != TokenKind::MacroName)
    error(cur_, "expected the name of the macro, found " + cur_.describe());
  auto m = std::make_shared<Macro>();
  m->name = std::string(cur_.text());
  m->loc = cur_.loc();
  if (cur_.kind == TokenKind::MacroName) tables_[0].erase(m->name);
  getToken();
  if (!cur_.is("(")) error(cur_, "expected '(' after the macro's name, found " + cur_.describe());
  for (;;) {
    getToken();
    if (cur_.is(")")) break;
    if (cur_.kind != TokenKind::Undeclared && cur_.kind != TokenKind::Identifier &&
        cur_.kind != TokenKind::MacroName)
      error(cur_, "expected a parameter name or ')', found " + cur_.describe());
    if (cur_.macro && cur_.macro->name == m->name)
      error(cur_, "cannot call a macro while declaring its parameters");
    m->params.emplace_back(cur_.text());
    if (m->params.size() > kMaxParameters)
      error(cur_, "too many parameters (POV-Ray takes at most 55)");
    parseComma();
  }
  okToDeclare_ = prevOk;
  m->file = levels_.back().file;
  m->bodyStart = levels_.back().pos;
  auto s = std::make_shared<Symbol>();
  s->kind = Symbol::Kind::Macro;
  s->macro = m;
  tables_[0][m->name] = s;  // macros are always global
  pendingMacro_ = m;
}

void TokenStream::invokeMacro(std::shared_ptr<Macro> m, SourceLoc callLoc) {
  if (static_cast<int>(tables_.size()) > options_.limits.macroDepth)
    error(callLoc, "macro calls and include files nested more than " +
                       std::to_string(options_.limits.macroDepth) +
                       " deep (the limit of POV-Ray and Lucent; endless recursion?)");
  getToken();
  if (!cur_.is("("))
    error(cur_, "expected '(' after macro '" + m->name + "', found " + cur_.describe());
  // Every argument is read before the macro's table exists, so that a recursive call sees
  // the caller's identifiers.
  std::vector<std::shared_ptr<Symbol>> args;
  for (size_t i = 0; i < m->params.size(); ++i) {
    auto s = std::make_shared<Symbol>();
    Ref byRef;
    if (!rvalue(s->value, &byRef, true, false)) {
      getToken();
      error(cur_, "macro '" + m->name + "' expects " + std::to_string(m->params.size()) +
                      " parameter" + (m->params.size() == 1 ? "" : "s") + " but only " +
                      std::to_string(i) + (i == 1 ? " was" : " were") + " given");
    }
    if (byRef.valid()) {
      s->kind = Symbol::Kind::Parameter;
      s->target = byRef;
    }
    args.push_back(s);
    parseComma();
  }
  getToken();
  if (!cur_.is(")"))
    error(cur_, "macro '" + m->name + "' takes " + std::to_string(m->params.size()) + " parameter" +
                    (m->params.size() == 1 ? "" : "s") + ": expected ')', found " +
                    cur_.describe());
  if (static_cast<int>(conds_.size()) >= options_.limits.conditionDepth)
    error(callLoc, "too many nested conditionals or macros (the limit is " +
                       std::to_string(options_.limits.conditionDepth) + ")");
  CondEntry c;
  c.type = Cond::InvokingMacro;
  c.loc = callLoc;
  c.directive = "macro call";
  c.macro = m;
  c.returnFile = levels_.back().file;
  c.returnPos = levels_.back().pos;
  conds_.push_back(std::move(c));
  tables_.emplace_back();
  for (size_t i = 0; i < args.size(); ++i) tables_.back()[m->params[i]] = args[i];
  notes_.push_back({callLoc, "in macro '" + m->name + "' called here"});
  levels_.back() = Level{m->file, m->bodyStart};
}

void TokenStream::returnFromMacro() {
  const CondEntry& c = conds_.back();
  levels_.back() = Level{c.returnFile, c.returnPos};
  tables_.pop_back();
  notes_.pop_back();
}

void TokenStream::openInclude(const SourceLoc& at) {
  std::string name;
  stringExpression(name, true, true);
  if (static_cast<int>(levels_.size()) > options_.limits.includeDepth)
    error(at, "include files nested more than " + std::to_string(options_.limits.includeDepth) +
                  " deep");
  if (static_cast<int>(tables_.size()) > options_.limits.macroDepth)
    error(at, "macro calls and include files nested more than " +
                  std::to_string(options_.limits.macroDepth) + " deep");
  std::string display;
  std::filesystem::path found = findInclude(name, at, display);
  SourceFile* f = load(found, display);
  levels_.push_back(Level{f, 0});
  tables_.emplace_back();
  notes_.push_back({at, "in the file included here"});
}

const std::filesystem::path& TokenStream::canonicalFolder(
    const std::filesystem::path& folder) const {
  auto it = canonicalFolders_.find(folder);
  if (it == canonicalFolders_.end())
    it = canonicalFolders_.emplace(folder, canonicalPath(folder)).first;
  return it->second;
}

std::filesystem::path TokenStream::findDataFile(const std::string& name, const SourceLoc& at,
                                                const std::vector<std::string>& extensions) const {
  std::string display;
  return findInclude(name, at, display, false, &extensions);
}

// POV-Ray's search: the scene's folder, then the library folders; a name without an
// extension is also tried with ".inc" (`tryInc`, for #include). A data file's name is tried
// with each of its type's `extensions` added, after the name as written if it already ends
// in one of them, before it otherwise (POV-Ray's FindFile).
std::filesystem::path TokenStream::findInclude(const std::string& name, const SourceLoc& at,
                                               std::string& display, bool tryInc,
                                               const std::vector<std::string>* extensions) const {
  namespace fs = std::filesystem;
  // A file looked for again (shapes.inc and its kin include each other, guarded; a macro
  // makes text in one font at each call) is found where it was found before: the files do
  // not move while a scene is read.
  std::string key = (tryInc ? "i\n" : "d\n") + name;
  if (extensions)
    for (const std::string& e : *extensions) key += "\n" + e;
  if (auto hit = foundIncludes_.find(key); hit != foundIncludes_.end()) {
    display = hit->second.display;
    return hit->second.path;
  }
  std::vector<fs::path> folders{sceneFolder_};
  for (const auto& f : options_.includeFolders) folders.push_back(f);
  std::vector<std::string> names{name};
  if (tryInc && fs::path(name).extension().empty()) names.push_back(name + ".inc");
  if (extensions) {
    const std::string ext = fs::path(name).extension().string();
    const bool exactFirst =
        !ext.empty() && std::find(extensions->begin(), extensions->end(), ext) != extensions->end();
    names.clear();
    if (exactFirst) names.push_back(name);
    for (const std::string& e : *extensions) names.push_back(name + e);
    if (!exactFirst) names.push_back(name);
  }
  for (size_t i = 0; i < folders.size(); ++i) {
    for (const std::string& n : names) {
      fs::path p = fs::path(n).is_absolute() ? fs::path(n) : folders[i] / n;
      std::error_code ec;
      if (!fs::is_regular_file(p, ec)) continue;
      display = fs::path(n).is_absolute() ? n
                : i == 0                  ? (sceneDisplayFolder_ / n).string()
                                          : (folders[i] / n).string();
      if (i == 0 && options_.access) {
        FileAccess::Resolved r = options_.access->resolve(n, sceneFolder_);
        if (!r.error.empty()) error(at, r.error);
        return r.path;
      }
      fs::path c = canonicalPath(p), root = canonicalFolder(folders[i]);
      // An include must lie inside the folder; a data file (a font, an image) may be a link
      // the folder holds (Debian links POV-Ray's fonts there), but its name must not leave it.
      auto rel = tryInc ? c.lexically_relative(root)
                        : p.lexically_normal().lexically_relative(folders[i].lexically_normal());
      if (!fs::path(n).is_absolute() && (rel.empty() || *rel.begin() == ".."))
        error(at, "'" + name + "' leads outside the folder " + root.string());
      if (fs::path(n).is_absolute() && options_.access) {
        FileAccess::Resolved r = options_.access->resolve(n, sceneFolder_);
        if (!r.error.empty()) error(at, r.error);
      } else {
        foundIncludes_[key] = FoundFile{c, display};
      }
      return c;
    }
  }
  std::string searched;
  for (const auto& f : folders) searched += (searched.empty() ? "" : ", ") + f.string();
  error(at, std::string(tryInc ? "cannot open include file '" : "cannot find the file '") + name +
                "' (searched " + searched + ")");
}

}  // namespace lucent::sdl
