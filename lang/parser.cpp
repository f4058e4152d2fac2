// The scene language's driver: loads the scene and its includes, then reads the
// top-level elements in phases (parameters while loading; named materials, so shapes may
// name a material declared after them; everything else in document order; references
// last), and returns the scene only if no error was found. Diagnostics come back sorted
// by file (in the order files were read), line and column.
#include "parser.h"

#include "camera_inside_warning.h"
#include "element_parsers.h"
#include "expansion.h"
#include "povray_names.h"
#include "scene_loader.h"

#include "scenegraph/digest.h"

#include "scenegraph/light_placement.h"
#include "scenegraph/located_error.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

namespace fs = std::filesystem;

namespace lucent {

namespace {

const std::vector<std::string_view>& topLevelElementNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> n{"render", "camera",  "light",  "material", "param",
                                    "defs",   "include", "repeat", "if",       "animation",
                                    "sky",    "fog",     "rainbow"};
    n.insert(n.end(), geometryElementNames().begin(), geometryElementNames().end());
    return n;
  }();
  return names;
}

// An element inside a top-level <repeat> or <if>: a geometry node or a light.
void readRepeated(ParseContext& ctx, const SourceFile& file, pugi::xml_node element) {
  std::string_view name = element.name();
  if (isGeometryElement(name) || name == "light") {
    Node& parent = name == "light" ? *ctx.scene.lightRoot : *ctx.scene.root;
    if (auto node = parseGeometryNode(ctx, file, element, 2))
      parent.children.push_back(std::move(node));
  } else {
    ElementReader(ctx, file, element)
        .error("<" + std::string(name) +
               "> is not allowed inside <repeat> or <if>; at the top level they hold "
               "geometry nodes and lights" +
               didYouMean(name, geometryElementNames()));
  }
}

void readTopLevel(ParseContext& ctx, const TopLevelItem& item) {
  ElementReader r(ctx, *item.file, item.element);
  std::string_view name = item.element.name();
  if (name == "param" || name == "material" || name == "animation")
    return;  // read in earlier phases
  if (name == "repeat" || name == "if") {
    // The element itself is expanded as the only child of a pseudo-parent: the scene root.
    ElementReader root(ctx, *item.file, item.file->root());
    expandElement(root, item.element, 2,
                  [&](pugi::xml_node c) { readRepeated(ctx, *item.file, c); });
    return;
  }
  if (name == "render") parseRender(r);
  else if (name == "fog") parseFog(r);
  else if (name == "rainbow") parseRainbow(r);
  else if (name == "camera") parseCamera(r);
  else if (name == "sky") parseSky(r);
  else if (name == "defs") parseDefs(r);
  else if (isGeometryElement(name) || name == "light") {
    Node& parent = name == "light" ? *ctx.scene.lightRoot : *ctx.scene.root;
    if (auto node = parseGeometryNode(ctx, *item.file, item.element, 1))
      parent.children.push_back(std::move(node));
  } else if (name == "checker" || name == "image" || name == "pattern" || name == "hexagon" ||
             name == "brick") {
    r.error("<" + std::string(name) + "> is a texture: it goes inside a <material>");
  } else if (name == "normal" || name == "bump-map") {
    r.error("<" + std::string(name) +
            "> perturbs a material's normal: it goes inside a <material>");
  } else {
    std::string pov = povrayElementHint("scene", name);
    r.error("unknown element <" + std::string(name) + "> in <scene>" +
            (pov.empty() ? didYouMean(name, topLevelElementNames()) : pov));
  }
}

// Errors of several phases are collected out of order: sort them as a reader would go.
Diagnostics sorted(const Diagnostics& in, const std::vector<std::unique_ptr<SourceFile>>& files) {
  std::unordered_map<std::string, size_t> rank;
  for (size_t i = 0; i < files.size(); ++i) rank.emplace(files[i]->display(), i);
  std::vector<Diagnostic> all = in.all();
  auto key = [&](const Diagnostic& d) {
    auto it = rank.find(d.loc.file);
    return std::make_tuple(it == rank.end() ? files.size() : it->second, d.loc.line, d.loc.col);
  };
  std::stable_sort(all.begin(), all.end(),
                   [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
  Diagnostics out;
  for (Diagnostic& d : all) {
    if (d.severity == Severity::Error) out.error(d.loc, std::move(d.message));
    else out.warning(d.loc, std::move(d.message));
  }
  return out;
}

// Feeds the elements, attributes and text under `root` to `d`, comments and layout left
// out. Iterative: a file may nest elements far deeper than the stack allows recursion.
void digestXml(pugi::xml_node root, Digest& d) {
  for (pugi::xml_node n = root.first_child(); n;) {
    if (n.type() == pugi::node_element) {
      d.field("<").field(n.name());
      for (pugi::xml_attribute a : n.attributes()) d.field(a.name()).field(a.value());
      if (n.first_child()) {
        n = n.first_child();
        continue;
      }
      d.field(">");
    } else if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata) {
      d.field("text").field(n.value());
    }
    while (!n.next_sibling()) {
      n = n.parent();
      if (n == root) return;
      d.field(">");
    }
    n = n.next_sibling();
  }
}

ParseResult parseText(std::string text, const std::string& path, const ParseOptions& options,
                      bool isFile) {
  ParseResult result;
  auto scene = std::make_unique<Scene>();
  scene->file = path;
  Diagnostics diags;
  Parameters params(options.defines, diags);
  fs::path folder = fs::path(path).parent_path();
  FileAccess files(folder.empty() ? fs::path(".") : folder, options.allowPaths,
                   options.replay.get(), options.onGrant);
  ParseContext ctx{*scene, diags, params, files};
  if (options.meshCache) ctx.meshCache = options.meshCache;
  SceneLoader loader(ctx);

  try {
    auto top = std::make_unique<SourceFile>(
        path, canonicalPath(folder.empty() ? fs::path(".") : folder), std::move(text));
    if (loader.load(std::move(top))) {
      for (const SourceFile* f : loader.sceneFiles()) checkSceneRoot(ctx, *f);
      readAnimation(ctx, loader.items(), options.frame);
      parseNamedMaterials(ctx, loader.items());
      for (const TopLevelItem& item : loader.items()) readTopLevel(ctx, item);
      resolveReferences(ctx);
      if (!diags.hasErrors()) {
        try {
          scene->lights = placeLights(*scene, static_cast<size_t>(kMaxExpandedNodes));
        } catch (const LocatedError& e) {
          diags.error(e.loc(), e.message());
        }
      }
      if (scene->cameras.empty()) {
        const SourceFile& topFile = *loader.files().front();
        diags.error(topFile.loc(topFile.root()),
                    "the scene has no <camera> (at least one is required)");
      }
      if (!diags.hasErrors()) warnCamerasInsideOpaqueSolids(*scene, diags);
      for (const std::string& name : params.unusedDefines())
        diags.warning(SourceLoc{path, 0, 0}, "-D " + name + " is not used by the scene");
    }
  } catch (const std::exception& e) {
    // Nothing an input contains should get here; if it does, fail cleanly, not crash.
    diags.error(SourceLoc{path, 0, 0},
                std::string("internal error while reading the scene: ") + e.what());
  }

  result.diagnostics = sorted(diags, loader.files());
  if (isFile) result.sources.push_back(canonicalPath(path));
  for (const fs::path& f : files.granted()) {
    const bool source = loader.sourcePaths().count(f) > 0;
    std::vector<fs::path>& list = source ? result.sources : result.dataFiles;
    if (std::find(list.begin(), list.end(), f) == list.end()) list.push_back(f);
  }
  result.grants = files.grants();
  Digest digest;
  for (const auto& f : loader.files()) digestXml(f->root().parent(), digest.field("file"));
  result.xmlDigest = digest.value();
  result.animation = scene->animation;
  result.frame = scene->frame;
  result.clock = scene->clock;
  if (!diags.hasErrors()) result.scene = std::move(scene);
  return result;
}

}  // namespace

ParseResult parseSceneFile(const std::string& path, const ParseOptions& options) {
  std::string text;
  std::optional<std::string> problem = readSceneText(path, text);
  if (problem) {
    ParseResult result;
    result.ioFailure = true;
    result.diagnostics.error(SourceLoc{path, 0, 0}, "cannot read the scene file: " + *problem);
    return result;
  }
  return parseText(std::move(text), path, options, true);
}

ParseResult parseSceneString(const std::string& xml, const std::string& virtualPath,
                             const ParseOptions& options) {
  return parseText(xml, virtualPath, options, false);
}

}  // namespace lucent
