// State shared by the element parsers while one scene is read: the scene being filled,
// the diagnostics, parameters, file access, and the names (ids) seen so far.
#pragma once

#include "diagnostics.h"
#include "file_access.h"
#include "parameters.h"
#include "scope.h"
#include "source_file.h"

#include "meshes/mesh_file_cache.h"
#include "scenegraph/object_pattern.h"
#include "scenegraph/scene.h"

#include <pugixml.hpp>

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace lucent {

// Elements nest at most this deep in a file (checked before recursing, so a hostile
// 100,000-deep file gives an error, not a stack overflow) ...
constexpr int kMaxElementDepth = 256;
// ... and nodes at most this deep counting what <use> instantiates, so that building the
// world (which recurses) stays far from the stack limit.
constexpr int kMaxInstanceDepth = 1024;
// Files included within included files, at most this deep.
constexpr int kMaxIncludeDepth = 16;
// <repeat>, <if> and parameterised <use> expand a scene to at most this many nodes and
// lights: a scene that would exceed it is refused before it expands (expansion.cpp).
constexpr long long kMaxExpandedNodes = 10'000'000;

// A top-level element of the scene, after <include>s were replaced by their files' children.
struct TopLevelItem {
  const SourceFile* file;
  pugi::xml_node element;
};

struct ParseContext {
  ParseContext(Scene& s, Diagnostics& d, Parameters& p, const FileAccess& f)
      : scene(s), diags(d), params(p), files(f) {}

  Scene& scene;
  Diagnostics& diags;
  Parameters& params;
  const FileAccess& files;

  // Named materials: id -> index into scene.materials.
  std::unordered_map<std::string, uint32_t> materialIds;
  // The indices of the materials whose diffuse was written, by themselves or along their
  // base= chain: a texture shows as it is only where no diffuse was written.
  std::unordered_set<uint32_t> materialsWithDiffuse;
  // Where the <material default="true"> is, once one was read (at most one).
  std::optional<SourceLoc> defaultMaterialLoc;

  // The scope of the element being read: local <param>s and <repeat> variables (null at
  // the top level).
  ScopePtr scope;
  // Nodes and lights made so far, against kMaxExpandedNodes; once over it, expansion stops.
  long long nodeCount = 0;
  bool overLimit = false;
  // The outermost <repeat> being expanded (to blame when the limit is crossed).
  const SourceFile* outerRepeatFile = nullptr;
  pugi::xml_node outerRepeat;

  // Node ids (one namespace for <defs> and the main tree) and the <use>s to resolve. A node
  // keeps the element and scope it was read in, so a <use> with parameters can read it again.
  struct IdEntry {
    Node* node;
    SourceLoc loc;
    const SourceFile* file = nullptr;
    pugi::xml_node element;
    ScopePtr scope;
  };
  std::unordered_map<std::string, IdEntry> nodeIds;
  struct PendingUse {
    Node* use;
    std::string ref;
    SourceLoc refLoc;  // the value of the ref attribute
  };
  std::vector<PendingUse> uses;
  // <use>s with <param> children: instantiated once every id is known (references.cpp).
  struct PendingInstance {
    Node* use;
    std::string ref;
    SourceLoc refLoc;
    ScopePtr scope;                  // the <use>'s own scope, holding its <param>s
    std::vector<std::string> chain;  // the definitions being instantiated around it
  };
  std::vector<PendingInstance> instances;
  // While an instance is read: its definitions chain, and the <use>'s scope whose <param>s
  // hide the definition's own; ids inside an instance are not registered (they are copies).
  std::vector<std::string> instanceChain;
  ScopePtr instanceParams;
  bool registerIds = true;
  // Nodes whose own element had errors: later checks (CSG solids) skip them rather than
  // repeat the problem in other words.
  std::unordered_set<const Node*> broken;
  // Nodes with a <clip> or <bound>: their solids are checked once references are known.
  std::vector<const Node*> clipped;
  // <pattern type="object" object="id">s: the node named and its solid found once every id
  // is known (references.cpp), then given to the pattern.
  struct PendingObjectPattern {
    std::shared_ptr<ObjectPattern> pattern;
    SourceLoc loc;    // the value of the object attribute
    std::string tag;  // "<pattern>" or "<normal>"
  };
  std::vector<PendingObjectPattern> objectPatterns;

  // Meshes read from files, by canonical path: a file used twice is read once (and once
  // for all the parses that share ParseOptions::meshCache).
  std::shared_ptr<MeshFileCache> meshCache = std::make_shared<MeshFileCache>();

  // The pattern element of the <material-map> being read: the only image-pattern that may
  // say index="true" (its value picks an entry by number).
  pugi::xml_node mapPatternElement;

  // Camera names, for duplicates.
  std::unordered_map<std::string, SourceLoc> cameraNames;
  // Where <render> was given, to refuse a second one.
  SourceLoc renderLoc;
  bool hasRender = false;
};

}  // namespace lucent
