// Lucent's scene language: reads scene files (XML, the contract in docs/scene-language.md)
// into a scene graph, reporting every error it can with file:line:col.
#pragma once

#include "diagnostics.h"
#include "file_access.h"

#include "scenegraph/scene.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lucent {

class MeshFileCache;  // meshes/mesh_file_cache.h

struct ParseOptions {
  // -D name=value: wins over <param> declarations.
  std::map<std::string, std::string> defines;
  // Folders (besides the scene file's own) that the scene may read files from.
  std::vector<std::string> allowPaths;
  // The frame of an animated scene to expand (1-based): it sets the built-in names frame
  // and clock. -D frame=F or -D clock=C win over it.
  int frame = 1;
  // Mesh files already read, to share with this parse (and to fill): a caller that parses
  // many scenes, as the frames of an animation, keeps one. Null: a cache for this parse.
  std::shared_ptr<MeshFileCache> meshCache;
  // Set on a process of a distributed render that was sent the scene's files: names
  // resolve to the copies (FileReplay); null: the files themselves, by the access rule.
  std::shared_ptr<const FileReplay> replay;
  // Told of each file name the parse is granted, as it is (lucent-mpi's rank 0 sends the
  // file to the other ranks then, while they parse too).
  GrantObserver onGrant;
};

struct ParseResult {
  std::unique_ptr<Scene> scene;  // null when there are errors
  Diagnostics diagnostics;       // errors (then scene is null) and warnings
  // The scene file itself could not be read (missing, a folder, unreadable): an
  // input/output failure rather than an invalid scene (exit status 3, not 2).
  bool ioFailure = false;
  // The scene's <animation> and the frame read, also when there are errors (so that a
  // message can name the frame).
  Animation animation;
  int frame = 1;
  double clock = 0.0;
  // Every file read, by canonical path: `sources`, the scene file (when it is one) and the
  // files it includes; `dataFiles`, the meshes, images, fonts and height maps it reads, in
  // the order first read.
  std::vector<std::filesystem::path> sources, dataFiles;
  // The names each was read by (what a distributed render sends with the files).
  std::vector<FileGrant> grants;
  // A digest of the scene's XML after includes (elements, attributes and text of the scene
  // file and every file it includes, in order; comments and layout left out): with the -D
  // values, the frame and the files read, everything the expanded scene is made of.
  uint64_t xmlDigest = 0;
};

// Parses and validates the scene file at `path`.
ParseResult parseSceneFile(const std::string& path, const ParseOptions& options = {});

// Parses a scene held in memory; `virtualPath` names it in messages and anchors relative
// paths (for tests and fuzzing).
ParseResult parseSceneString(const std::string& xml, const std::string& virtualPath,
                             const ParseOptions& options = {});

}  // namespace lucent
