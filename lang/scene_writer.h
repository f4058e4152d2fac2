// The scene writer behind `lucent convert`: a Scene, as the scene language (or the POV-Ray
// importer) made it, written back as an equivalent Lucent XML scene. Everything the
// language computed is already expanded in the Scene (repeats, expressions, uses of
// parameters), so the file holds plain values. The attributes of shapes, cameras, lights and
// finish terms are found through their tables (attribute_probe.h), not listed here.
#pragma once

#include "scenegraph/scene.h"

#include <string>

namespace lucent {

struct WriteOptions {
  // The folder the written file will be in: file references (meshes, images) are written
  // relative to it. Empty: the current folder.
  std::string folder;
};

// The scene as XML. What the writer cannot write yet throws a LocatedError naming the
// element and its source location: a file is never written with it left out.
std::string writeSceneXml(const Scene& scene, const WriteOptions& options);

// One material as a top-level `<material id="ID" ...>` element of a scene (its children
// included), as writeSceneXml writes a shared one: for libraries of materials.
std::string writeMaterialXml(const Material& material, const std::string& id,
                             const WriteOptions& options);

}  // namespace lucent
