// The node hierarchy as POV-Ray objects: every primitive, CSG operations, transforms as
// `matrix`, and the material of each leaf.
//
// Groups and <use> are flattened exactly as the World builds them (scenegraph/world.cpp):
// their children join the enclosing list (the scene's top level or a CSG operation's
// operands), with the group's transform composed in, so POV-Ray sees the same objects and
// the same CSG operands. Every leaf carries its own resolved material (POV-Ray lets a
// CSG's texture reach only children without one, and a texture written inside a leaf
// before its transform is evaluated in the leaf's object space, where Lucent evaluates a
// checker). Meshes are declared once (mesh2) and instanced with `object`. The interior
// (ior, absorption) of a merge, intersection or difference is written once, on the CSG
// object, and shared by the leaves of the same material: POV-Ray tells entering from
// leaving by the interior a ray carries, so a ray entering a lens through one sphere and
// leaving through the other must meet the same interior (with one per leaf it takes the
// exit for an entry into a second glass and does not bend there; Lucent bends there).
// shadows="false" is POV-Ray's no_shadow on each leaf (POV-Ray splits unions into their
// children, so a union's parts keep their own) or on the whole merge, intersection or
// difference, whose parts' no_shadow POV-Ray ignores; so are image="false" and
// reflection="false" as no_image and no_reflection. double-illuminate and interior-material
// go on every leaf as double_illuminate and interior_texture.
#pragma once

#include "pov_materials.h"
#include "pov_writer.h"

#include "scenegraph/scene.h"

#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace lucent {

class PovGeometry {
 public:
  // `camera` is the camera's world position: planes that contain it are written facing the
  // other way (see writeScene), so that POV-Ray does not start the camera ray inside them.
  PovGeometry(const Scene& scene, const PovMaterials& materials, const Vec3& camera,
              PovIssues& issues);

  // Writes every top-level object into `objects` and the mesh declarations they use into
  // `declarations`; `used` gets the indices of the materials referenced.
  void write(PovWriter& declarations, PovWriter& objects);
  // `#declare NAME = object|union { ... }` of every object pattern's node (its geometry,
  // without textures), for the materials that name it (povObjectPatternName).
  void writeObjectPatterns(PovWriter& out);
  const std::vector<bool>& usedMaterials() const { return used_; }
  // A placed light's projected_through block: its <projected-through> objects (geometry
  // only, as a clip's) in the light's place. A mesh among them is declared with the meshes
  // write() gives, so the light is written after them (takeMeshDeclarations).
  void writeProjection(const Light& light, PovWriter& out);
  // The mesh declarations made since write() handed its own over.
  void takeMeshDeclarations(PovWriter& out);

 private:
  void writeNode(const Node& node, const Mat4& fromContext, uint32_t inherited, bool topLevel,
                 PovWriter& out);
  // POV-Ray's light_group of a <light-group>: its own lights, then the node written as a
  // group, then global_lights.
  void writeLightGroup(const Node& node, const Mat4& fromContext, uint32_t inherited, bool topLevel,
                       PovWriter& out);
  void writeLeaf(const Node& node, const Mat4& m, uint32_t material, bool topLevel, PovWriter& out);
  void writeShapeHead(const Node& node, const Mat4& m, uint32_t material, bool topLevel,
                      bool& inverse, PovWriter& out);
  std::string meshName(const MeshSpec& mesh, const Node& node);
  // A node's clipped_by or bounded_by block: its solids below `m`.
  // Runs `write` with the flags of shapes written as solids of their own (clips, bounds).
  void asOwnSolids(const std::function<void()>& write);
  void writeSolids(const char* keyword, const std::vector<std::unique_ptr<Node>>& solids,
                   const Mat4& m, uint32_t material, PovWriter& out);
  // Takes the node's flags into marks_ (the caller restores them).
  void markNode(const Node& node);
  // no_shadow, no_image, no_reflection as marks_ says.
  void writeVisibility(PovWriter& out) const;
  // Does a leaf of `material` write an interior_texture (marking its material used)?
  bool writesInterior(uint32_t material);
  bool uvMappedHere(uint32_t material) const;
  // Operands a CSG node gets once groups and <use> are flattened.
  int operandCount(const Node& node) const;

  const Scene& scene_;
  const PovMaterials& materials_;
  Vec3 camera_;
  PovIssues& issues_;
  std::vector<bool> used_;
  PovWriter meshDeclarations_;
  std::map<std::pair<const MeshData*, SmoothMode>, std::string> meshNames_;
  // The material whose interior the enclosing merge, intersection or difference holds:
  // leaves of that material leave theirs out, so POV-Ray sees one shared interior.
  std::optional<uint32_t> csgInterior_;
  // shadows="false" as no_shadow, as the World reads it: `marks_` is inherited by
  // the node being written; inside a merge, intersection or difference the parts' own
  // flags are ignored (`ignoreOwnShadows_`), and a written one carries no_shadow itself
  // (`inWrittenSolid_`: its parts write none).
  // The same for image="false" and reflection="false" (no_image, no_reflection); and the
  // double-illuminate and interior-material a leaf inherits, written on every leaf.
  struct Marks {
    bool noShadow = false, noImage = false, noReflection = false;
    bool doubleIlluminate = false;
    std::optional<uint32_t> interior;
  };
  Marks marks_;
  bool ignoreOwnShadows_ = false;
  bool inWrittenSolid_ = false;
  // inverse="true" still to be written: by the next object opened (a leaf or a CSG block),
  // so that a group or <use> of one operand passes it down; two inverses cancel.
  bool pendingInverse_ = false;
  const Node* boundWritten_ = nullptr;
  const Node* lightGroupWritten_ = nullptr;  // the light group whose body is being written
  bool inClipOrBound_ = false;  // writing a clip's or bound's solids: no textures  // the node
                                // whose bounded_by union is being written
  // Takes the pending inverse for the object being opened.
  bool takeInverse() {
    const bool inv = pendingInverse_;
    pendingInverse_ = false;
    return inv;
  }
};

// Should a top-level plane be written facing the other way because the camera is inside
// it? `worldFromObject` places the plane. (POV-Ray starts camera rays inside every object
// that contains the camera; inside two, surfaces act as overlaps without refraction.)
bool cameraInsidePlane(const PlaneSpec& plane, const Mat4& worldFromObject, const Vec3& camera);

}  // namespace lucent
