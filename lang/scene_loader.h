// Reads the scene file and, through <include src>, the files it includes, into one list of
// top-level elements (each include replaced by its file's top-level children, in place).
// Parameters are collected on the way: a file's own <param>s first, then its includes in
// order, so an include's src may use the parameters of its own file, of files included
// before it, and -D.
//
// Include rules: the path is relative to the including file and must obey the file access
// rule; a file that includes itself, directly or not, is an error naming the chain;
// includes nest at most kMaxIncludeDepth deep; a file already included elsewhere is not
// inserted again (as #pragma once), so two files may share a library of materials.
#pragma once

#include "parse_context.h"

#include <filesystem>
#include <memory>
#include <set>
#include <vector>

namespace lucent {

class SceneLoader {
 public:
  explicit SceneLoader(ParseContext& ctx) : ctx_(ctx) {}

  // Parses `top` and everything it includes. False if the top file cannot be used at all
  // (an XML syntax error or a root other than <scene>).
  bool load(std::unique_ptr<SourceFile> top);

  const std::vector<TopLevelItem>& items() const { return items_; }
  // Every file read, the scene file first (they own the XML the items point into).
  const std::vector<std::unique_ptr<SourceFile>>& files() const { return files_; }
  // The files whose root is one <scene>: the others were refused whole, with one error.
  const std::vector<const SourceFile*>& sceneFiles() const { return scenes_; }
  // The canonical paths of the scene file and every file it includes.
  const std::set<std::filesystem::path>& sourcePaths() const { return seen_; }

 private:
  struct Open {
    std::filesystem::path canonical;
    std::string display;
  };
  bool parseFile(SourceFile& file, bool included);
  void expand(const SourceFile& file);
  void include(const SourceFile& from, pugi::xml_node element);
  void collectParams(const SourceFile& file);

  ParseContext& ctx_;
  std::vector<std::unique_ptr<SourceFile>> files_;
  std::vector<const SourceFile*> scenes_;
  std::vector<TopLevelItem> items_;
  std::vector<Open> stack_;               // the chain of files being expanded
  std::set<std::filesystem::path> seen_;  // every file read, by canonical path
};

// The root element's attributes: version="1" is required. Called once parameters are known.
void checkSceneRoot(ParseContext& ctx, const SourceFile& file);

}  // namespace lucent
