#include "scene_loader.h"

#include "did_you_mean.h"
#include "element_reader.h"
#include "library.h"

namespace fs = std::filesystem;

namespace lucent {

bool SceneLoader::parseFile(SourceFile& file, bool included) {
  if (auto syntax = file.parse()) {
    ctx_.diags.error(syntax->loc, syntax->message);
    return false;
  }
  pugi::xml_node root = file.root();
  // The root first: a file of several <material>s is one mistake (not a scene), not two.
  if (std::string_view(root.name()) != "scene") {
    ctx_.diags.error(file.loc(root),
                     "the root element must be <scene version=\"1\">, got <" +
                         std::string(root.name()) + ">" +
                         didYouMean(root.name(), std::vector<std::string_view>{"scene"}) +
                         (included ? "; an included file is a scene file too: put its "
                                     "elements inside <scene version=\"1\">"
                                   : ""));
    return false;
  }
  // pugixml accepts several top-level elements (and text beside them); an XML document,
  // and so a scene, has exactly one root. A second one would be silently ignored.
  for (pugi::xml_node n = root.next_sibling(); n; n = n.next_sibling()) {
    if (n.type() == pugi::node_element) {
      ctx_.diags.error(file.loc(n), "a second root element <" + std::string(n.name()) +
                                        "> after <" + root.name() +
                                        ">: a scene file has exactly one root element");
      return false;
    }
    if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata) {
      ctx_.diags.error(file.locOf(n.value()).value_or(file.loc(root)),
                       "text after the root element <" + std::string(root.name()) + ">");
      return false;
    }
  }
  scenes_.push_back(&file);
  return true;
}

bool SceneLoader::load(std::unique_ptr<SourceFile> top) {
  SourceFile& file = *top;
  files_.push_back(std::move(top));
  if (!parseFile(file, false)) return false;
  fs::path canonical = canonicalPath(ctx_.scene.file.empty() ? file.display() : ctx_.scene.file);
  seen_.insert(canonical);
  stack_.push_back({canonical, file.display()});
  collectParams(file);
  expand(file);
  stack_.pop_back();
  return true;
}

void SceneLoader::collectParams(const SourceFile& file) {
  for (pugi::xml_node c = file.root().first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element || std::string_view(c.name()) != "param") continue;
    ElementReader r(ctx_, file, c);
    r.checkAttributes({"name", "value"});
    r.forEachChild([&](pugi::xml_node n) {
      ElementReader(ctx_, file, n)
          .error("<param> takes no child elements, got <" + std::string(n.name()) + ">");
    });
    if (!r.has("name") || !r.has("value")) {
      r.error("<param> needs 'name' and 'value'");
      continue;
    }
    std::string name = r.verbatim("name");
    if (!Parameters::isValidName(name)) {
      r.attrError("name",
                  "a parameter name is letters, digits and '_', not starting with a digit; got '" +
                      name + "'");
      continue;
    }
    ctx_.params.declare(name, r.verbatim("value"), file, c);
  }
}

void SceneLoader::expand(const SourceFile& file) {
  ElementReader root(ctx_, file, file.root());
  root.forEachChild([&](pugi::xml_node c) {
    if (std::string_view(c.name()) == "include") include(file, c);
    else items_.push_back({&file, c});
  });
}

void SceneLoader::include(const SourceFile& from, pugi::xml_node element) {
  ElementReader r(ctx_, from, element);
  r.checkAttributes({"src"});
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader(ctx_, from, n)
        .error("<include> takes no child elements, got <" + std::string(n.name()) + ">");
  });
  if (!r.has("src")) {
    r.error("<include> needs a 'src' attribute (the scene file to insert)");
    return;
  }
  auto src = r.text("src");
  if (!src) return;
  const bool fromLibrary = src->rfind(kLibraryPrefix, 0) == 0;
  FileAccess::Resolved f;
  std::string display;
  std::optional<std::string_view> libraryText;
  if (fromLibrary) {
    // The shipped library: compiled in, so no file access is involved.
    const std::string name = src->substr(kLibraryPrefix.size());
    libraryText = libraryFile(name);
    if (!libraryText) {
      std::vector<std::string_view> names = libraryFileNames();
      std::string list;
      for (std::string_view n : names) list += (list.empty() ? "" : ", ") + std::string(n);
      r.attrError("src", "the library has no file '" + name + "'" + didYouMean(name, names) +
                             " (it has " + list + ")");
      return;
    }
    f.path = *src;  // the key for include cycles and repeats
    display = *src;
  } else {
    f = ctx_.files.resolve(*src, from.folder());
    if (f.path.empty()) {
      r.attrError("src", f.error);
      return;
    }
    fs::path written(*src);
    display = written.is_absolute()
                  ? written.lexically_normal().string()
                  : (fs::path(from.display()).parent_path() / written).lexically_normal().string();
  }
  for (size_t i = 0; i < stack_.size(); ++i) {
    if (stack_[i].canonical != f.path) continue;
    std::string chain;
    for (size_t j = i; j < stack_.size(); ++j) chain += stack_[j].display + " -> ";
    r.attrError("src", "include cycle: " + chain + display);
    return;
  }
  if (static_cast<int>(stack_.size()) >= kMaxIncludeDepth) {
    r.attrError("src", "includes nest deeper than " + std::to_string(kMaxIncludeDepth) + " files");
    return;
  }
  if (!seen_.insert(f.path).second) return;  // included already: insert once

  std::string text;
  if (libraryText) {
    text = *libraryText;
  } else if (auto problem = readSceneText(f.path, text)) {
    r.attrError("src", "cannot read '" + *src + "': " + *problem);
    return;
  }
  // A library file names no other files (but lucent: ones), so its folder is never used.
  files_.push_back(std::make_unique<SourceFile>(
      display, fromLibrary ? fs::path(".") : f.path.parent_path(), std::move(text)));
  SourceFile& file = *files_.back();
  if (!parseFile(file, true)) return;
  stack_.push_back({f.path, display});
  collectParams(file);
  expand(file);
  stack_.pop_back();
}

void checkSceneRoot(ParseContext& ctx, const SourceFile& file) {
  ElementReader r(ctx, file, file.root());
  // Namespace declarations and xsi: attributes let an editor find the schema
  // (xsi:noNamespaceSchemaLocation="lucent.xsd"); they mean nothing to Lucent.
  std::vector<std::string_view> allowed{"version"};
  for (pugi::xml_attribute a = file.root().first_attribute(); a; a = a.next_attribute()) {
    std::string_view n = a.name();
    if (n == "xmlns" || n.rfind("xmlns:", 0) == 0 || n.rfind("xsi:", 0) == 0) allowed.push_back(n);
  }
  r.checkAttributes(allowed);
  if (!r.has("version")) {
    r.error("<scene> needs version=\"1\" (the version of the scene language it is written in)");
    return;
  }
  if (auto v = r.text("version"); v && trim(*v) != "1")
    r.attrError("version", "unknown version '" + *v + "'; this is version 1 of the scene language");
}

}  // namespace lucent
