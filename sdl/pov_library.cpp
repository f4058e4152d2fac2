#include "pov_library.h"

#include "scene_reader.h"
#include "token_stream.h"

#include "lang/scene_writer.h"

#include <fmt/format.h>

#include <map>
#include <set>
#include <stdexcept>

namespace lucent::sdl {

namespace {

constexpr const char* kSceneName = "pov-library.pov";

// What a declared item is used as on a sphere, by its kind; "" for kinds the library skips
// (finishes, normals, interiors and objects name no whole appearance).
std::string useOf(std::string_view kind) {
  if (kind == "texture" || kind == "pigment" || kind == "material") return std::string(kind);
  return "";
}

std::string prelude() {
  // assumed_gamma 1: colours are linear, as Lucent's are.
  std::string text = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n";
  for (const std::string& inc : povLibraryIncludes()) text += "#include \"" + inc + "\"\n";
  return text;
}

// Text for an XML comment, which may hold anything but "--".
std::string commentText(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '-' && !out.empty() && out.back() == '-') out += ' ';
    out += c;
  }
  return out;
}

struct Declared {
  std::map<std::string, std::array<double, 5>> colours;
  std::map<std::string, std::string> items;  // name -> texture, pigment or material
};

// The includes' global declarations of colours and of whole appearances.
Declared readDeclarations(const Options& options) {
  Scene scene;
  Diagnostics diagnostics;
  SceneReader reader(scene, diagnostics, options);
  TokenStream in(options, &reader);
  try {
    in.openText(kSceneName, prelude(), ".");
    reader.readScene(in);
  } catch (const LocatedError& e) {
    throw std::runtime_error(e.loc().str() + ": error: " + e.message());
  }
  Declared d;
  for (const std::string& name : in.globalNames()) {
    const Value* v = in.lookup(name);
    if (!v) continue;
    if (v->type == ValueType::Colour) d.colours[name] = v->v;
    if (v->type == ValueType::Item && v->item) {
      std::string use = useOf(v->item->kind());
      if (!use.empty()) d.items[name] = use;
    }
  }
  return d;
}

}  // namespace

const std::vector<std::string>& povLibraryIncludes() {
  static const std::vector<std::string> includes = {"colors.inc", "textures.inc", "woods.inc",
                                                    "stones.inc", "metals.inc",   "golds.inc",
                                                    "glass.inc"};
  return includes;
}

PovLibraryText makePovLibrary(const Options& given) {
  const Declared declared = readDeclarations(given);
  std::map<std::string, std::string> items = declared.items;
  PovLibraryText out;
  CollectedOutput output;
  Options options = given;
  options.output = &output;
  // Each declaration used once on a sphere of its own line; a use that gives an error (a
  // feature Lucent cannot render) is left out and the rest read again.
  for (int round = 0;; ++round) {
    std::string text = prelude();
    const int firstLine = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
    std::vector<std::string> byLine;
    for (const auto& [name, use] : items) {
      text += "sphere { 0, 1 " + use + " { " + name + " } }\n";
      byLine.push_back(name);
    }
    output.warnings.clear();
    SceneLoad load = loadSceneText(kSceneName, text, ".", options);
    if (load.scene) {
      std::map<int, std::string> warnings;  // by line of the scene
      for (const Diagnostic& d : load.diagnostics.all())
        if (d.severity == Severity::Warning) warnings[d.loc.line] += d.message + " ";
      // The approximations said in the include files (once each, whichever use met them).
      std::set<std::string> general(output.warnings.begin(), output.warnings.end());
      for (const Diagnostic& d : load.diagnostics.all())
        if (d.severity == Severity::Warning && d.loc.file != kSceneName) general.insert(d.str());
      const WriteOptions write;
      std::string body;
      for (const auto& node : load.scene->root->children) {
        const int k = node->loc.line - firstLine;
        if (node->loc.file != kSceneName || k < 0 || k >= static_cast<int>(byLine.size()) ||
            !node->material)
          throw std::runtime_error("pov library: an object at " + node->loc.str() +
                                   " that names no declaration");
        if (auto w = warnings.find(node->loc.line); w != warnings.end())
          body += "  <!-- approximate: " + commentText(w->second) + "-->\n";
        Material m = load.scene->materials.at(*node->material);
        m.loc = SourceLoc{};  // the made-up scene's line is no source to name
        body += writeMaterialXml(m, "pov:" + byLine[k], write);
        out.materialNames.push_back("pov:" + byLine[k]);
        ++out.materials;
      }
      std::string head =
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- Made by lucent's "
          "POV-Ray importer from POV-Ray 3.7's";
      for (const std::string& inc : povLibraryIncludes()) head += " " + inc;
      head += " (sdl/pov_library.cpp); do not edit. -->\n";
      for (const std::string& w : general) head += "<!-- approximate: " + commentText(w) + " -->\n";
      for (const std::string& left : out.leftOut)
        head += "<!-- left out: " + commentText(left) + " -->\n";
      head += "<scene version=\"1\">\n";
      for (const auto& [name, c] : declared.colours) {
        head += fmt::format(
            "  <pov-color id=\"pov:{}\" rgb=\"{} {} {}\" filter=\"{}\" transmit=\"{}\"/>\n", name,
            float(c[0]), float(c[1]), float(c[2]), float(c[3]), float(c[4]));
        ++out.colours;
      }
      out.xml = head + body + "</scene>\n";
      return out;
    }
    // The uses that failed are left out; an error anywhere else is the includes' own.
    std::set<std::string> failed;
    for (const Diagnostic& d : load.diagnostics.all()) {
      if (d.severity != Severity::Error) continue;
      const int k = d.loc.line - firstLine;
      if (d.loc.file != kSceneName || k < 0 || k >= static_cast<int>(byLine.size()) || round > 8)
        throw std::runtime_error(d.str());
      if (failed.insert(byLine[k]).second) out.leftOut.push_back(byLine[k] + ": " + d.message);
    }
    for (const std::string& name : failed) items.erase(name);
  }
}

}  // namespace lucent::sdl
