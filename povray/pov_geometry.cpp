#include "pov_geometry.h"
#include "pov_coincident.h"
#include "pov_function.h"
#include "pov_lights.h"
#include "pov_patterns.h"
#include "scenegraph/light_placement.h"
#include "scenegraph/shape_registry.h"

#include "pov_smooth_normals.h"
#include "primitives/triangle_mesh.h"

#include <fmt/core.h>

#include <functional>

namespace lucent {

namespace {

// A direction unlikely to run along a mesh's edges or faces, for POV-Ray's inside test of
// closed meshes (a ray parity count).
const Vec3 kInsideVector(0.2672612419124244, 0.5345224838248488, 0.8017837257372732);

}  // namespace

bool cameraInsidePlane(const PlaneSpec& plane, const Mat4& m, const Vec3& camera) {
  Vec3 pointWorld = Vec3(m * Vec4(plane.normal * plane.offset, 1.0));
  Vec3 normalWorld = glm::transpose(glm::inverse(Mat3(m))) * plane.normal;
  return glm::dot(normalWorld, camera - pointWorld) < 0.0;
}

PovGeometry::PovGeometry(const Scene& scene, const PovMaterials& materials, const Vec3& camera,
                         PovIssues& issues)
    : scene_(scene),
      materials_(materials),
      camera_(camera),
      issues_(issues),
      used_(scene.materials.size(), false) {}

void PovGeometry::write(PovWriter& declarations, PovWriter& objects) {
  writeNode(*scene_.root, Mat4(1.0), 0, true, objects);
  takeMeshDeclarations(declarations);
}

void PovGeometry::takeMeshDeclarations(PovWriter& out) {
  out.append(meshDeclarations_);
  meshDeclarations_ = PovWriter();
}

void PovGeometry::writeProjection(const Light& light, PovWriter& out) {
  const Node& group = *light.projectedThrough;
  asOwnSolids([&] {
    out.open("projected_through");
    out.open(operandCount(group) == 1 ? "object" : "union");
    writeNode(group, light.worldFromLight, 0, false, out);
    out.close();
    out.close();
  });
}

namespace {

// The object patterns of a material, and one whose map POV-Ray cannot write (if any).
struct FoundObjects {
  std::vector<const ObjectPattern*> patterns;
  const ObjectPattern* unexportable = nullptr;
};

void collectObjectPatterns(const PatternSpec& s, FoundObjects& out);
void collectObjectPatterns(const Texture& t, FoundObjects& out);

void collectObjectPatterns(const std::vector<TextureMapEntry>& entries, FoundObjects& out) {
  for (const TextureMapEntry& e : entries) collectObjectPatterns(e.texture, out);
}

void collectObjectPatterns(const PatternSpec& s, FoundObjects& out) {
  if (s.type == PatternType::object && s.object && s.object->node)
    out.patterns.push_back(s.object.get());
  if (s.pigment) collectObjectPatterns(s.pigment->texture, out);
}

// An object pattern whose value is not 0 or 1 alone with a map of more than two entries:
// POV-Ray's list of two cannot stand for it.
bool beyondTwoEntries(const PatternSpec& s, size_t entries) {
  return s.type == PatternType::object && entries > 2 && !objectPatternTwoValued(s);
}

void collectObjectPatterns(const Texture& t, FoundObjects& out) {
  if (const auto* p = std::get_if<PatternTexture>(&t)) {
    if (beyondTwoEntries(p->pattern, std::max(p->map.entries.size(), p->pigments.size())))
      out.unexportable = p->pattern.object.get();
    collectObjectPatterns(p->pattern, out);
    collectObjectPatterns(p->pigments, out);
  }
  if (const auto* c = std::get_if<CheckerTexture>(&t)) collectObjectPatterns(c->pigments, out);
  if (const auto* h = std::get_if<HexagonTexture>(&t)) collectObjectPatterns(h->pigments, out);
  if (const auto* b = std::get_if<BrickTexture>(&t)) collectObjectPatterns(b->pigments, out);
  if (const auto* a = std::get_if<AverageTexture>(&t)) collectObjectPatterns(a->entries, out);
}

void collectObjectPatterns(const NormalSpec& n, FoundObjects& out) {
  if (beyondTwoEntries(n.pattern, n.map.size())) out.unexportable = n.pattern.object.get();
  collectObjectPatterns(n.pattern, out);
  for (const WeightedNormal& e : n.average) collectObjectPatterns(e.normal, out);
  for (const NormalMapEntry& e : n.map) collectObjectPatterns(e.normal, out);
}

void collectObjectPatterns(const Material& m, FoundObjects& out) {
  collectObjectPatterns(m.texture, out);
  collectObjectPatterns(m.mapPattern, out);
  if (m.normal) collectObjectPatterns(*m.normal, out);
  for (const Material& layer : m.layers) collectObjectPatterns(layer, out);
  for (const MaterialMapEntry& e : m.mapEntries) collectObjectPatterns(e.material, out);
}

}  // namespace

void PovGeometry::writeObjectPatterns(PovWriter& out) {
  std::vector<const ObjectPattern*> patterns;
  for (const Material& m : scene_.materials) {
    FoundObjects found;
    collectObjectPatterns(m, found);
    patterns.insert(patterns.end(), found.patterns.begin(), found.patterns.end());
    if (found.unexportable)
      issues_.error(m.loc, "the object pattern of '" + found.unexportable->id +
                               "' has a frequency or a wave and a map of more than two "
                               "entries, which POV-Ray's list of two cannot write");
  }
  std::map<std::string, const Node*> declared;
  for (const ObjectPattern* o : patterns) {
    const std::string name = povObjectPatternName(*o);
    auto [it, added] = declared.emplace(name, o->node);
    if (!added) {
      if (it->second != o->node)
        issues_.error(o->node->loc, "the ids '" + it->second->id + "' and '" + o->id +
                                        "' give one POV-Ray name, " + name +
                                        ", to the objects of two object patterns");
      continue;
    }
    // Its geometry only, as a clip's: POV-Ray asks the object's inside alone.
    out.line("// the object of an object pattern: <" + o->node->element + " id=\"" + o->id +
             "\"> " + o->node->loc.str());
    asOwnSolids([&] {
      out.open("#declare " + name + " = " + (operandCount(*o->node) == 1 ? "object" : "union"));
      writeNode(*o->node, Mat4(1.0), 0, false, out);
      out.close();
    });
  }
}

int PovGeometry::operandCount(const Node& node) const {
  switch (node.kind) {
    case NodeKind::Group: {
      int n = 0;
      for (const auto& c : node.children) n += operandCount(*c);
      return n;
    }
    case NodeKind::Use:
      return node.target ? operandCount(*node.target) : 0;
    case NodeKind::Shape:
      return 1;
    case NodeKind::Light:
      return 0;
    default: {
      int n = 0;
      for (const auto& c : node.children) n += operandCount(*c);
      return n > 0 ? 1 : 0;  // an empty CSG node is dropped, as the World drops it
    }
  }
}

void PovGeometry::writeLightGroup(const Node& node, const Mat4& fromContext, uint32_t inherited,
                                  bool topLevel, PovWriter& out) {
  if (inWrittenSolid_)
    issues_.error(node.loc,
                  "a <light-group> inside a merge, intersection or difference cannot be written: "
                  "POV-Ray's light_group is one operand there, Lucent's group its children");
  const Mat4 m = fromContext * node.parentFromNode;
  // The highlights of a shadowless light matter if any material has one.
  const bool anySpecular = materials_.anySpecular(std::vector<bool>(scene_.materials.size(), true));
  out.open("light_group", "<light-group> " + node.loc.str());
  // Its own lights, placed in the world as the top-level ones (those deeper are global and
  // written with them).
  for (const auto& c : node.children) {
    if (!c->isLight()) continue;
    const Node& lightNode = c->kind == NodeKind::Use ? *c->target : *c;
    const Mat4 world = c->kind == NodeKind::Use ? m * c->parentFromNode * lightNode.parentFromNode
                                                : m * c->parentFromNode;
    const Light placed = placedLight(*lightNode.light, world);
    writeLight(placed, anySpecular, out, issues_,
               [&](PovWriter& w) { writeProjection(placed, w); });
  }
  const Node* outer = lightGroupWritten_;
  lightGroupWritten_ = &node;
  writeNode(node, fromContext, inherited, topLevel, out);
  lightGroupWritten_ = outer;
  out.line(node.globalLights ? "global_lights on" : "global_lights off");
  out.close();
}

void PovGeometry::writeNode(const Node& node, const Mat4& fromContext, uint32_t inherited,
                            bool topLevel, PovWriter& out) {
  // In a clip, a bound or an object pattern's object nothing is lit: a plain group.
  if (node.lightGroup && lightGroupWritten_ != &node && !inClipOrBound_)
    return writeLightGroup(node, fromContext, inherited, topLevel, out);
  const Mat4 m = fromContext * node.parentFromNode;
  const uint32_t material = node.material.value_or(inherited);
  if (!node.bound.empty() && boundWritten_ != &node) {
    // POV-Ray keeps the bounded_by of a union (it drops that of a plain shape, keeping only
    // its box): a union of the one object holds Lucent's <bound> as it is.
    out.open("union", "<" + node.element + "> " + node.loc.str() + " (bounded)");
    const Node* outer = boundWritten_;
    boundWritten_ = &node;
    writeNode(node, fromContext, inherited, false, out);
    boundWritten_ = outer;
    writeSolids("bounded_by", node.bound, m, material, out);
    out.close();
    return;
  }
  if (!node.clip.empty() && (node.kind == NodeKind::Group || node.kind == NodeKind::Use)) {
    // Several objects clipped as one: POV-Ray's union of them with the clip (inverted as
    // one when asked, its clip not: as Lucent inverts before it clips).
    const bool inv = takeInverse() != node.inverse;
    const Marks outerMarks = marks_;
    markNode(node);
    out.open("union", "<" + node.element + "> " + node.loc.str() + " (clipped)");
    if (node.kind == NodeKind::Group)
      for (const auto& c : node.children) writeNode(*c, Mat4(1.0), material, false, out);
    else if (node.target) writeNode(*node.target, Mat4(1.0), material, false, out);
    writeSolids("clipped_by", node.clip, Mat4(1.0), material, out);
    if (!isIdentity(m)) out.line(povMatrix(m));
    if (inv) out.line("inverse");
    out.close();
    marks_ = outerMarks;
    return;
  }
  // The flags of the enclosing writes, restored on return.
  const Marks outerMarks = marks_;
  const bool outerIgnore = ignoreOwnShadows_, outerInSolid = inWrittenSolid_;
  markNode(node);
  const bool solid = node.kind == NodeKind::Merge || node.kind == NodeKind::Intersection ||
                     node.kind == NodeKind::Difference;
  if (node.inverse) {
    if ((node.kind == NodeKind::Group || node.kind == NodeKind::Use) && operandCount(node) > 1) {
      // Several objects inverted as one: POV-Ray's union of them, inverse.
      const bool inv = !takeInverse();
      out.open("union", "<" + node.element + "> " + node.loc.str() + " (inverse)");
      if (node.kind == NodeKind::Group)
        for (const auto& c : node.children) writeNode(*c, m, material, false, out);
      else if (node.target) writeNode(*node.target, m, material, false, out);
      if (inv) out.line("inverse");
      out.close();
      marks_ = outerMarks;
      pendingInverse_ = false;
      return;
    }
    pendingInverse_ = !pendingInverse_;
  }
  switch (node.kind) {
    case NodeKind::Group:
      for (const auto& c : node.children) writeNode(*c, m, material, topLevel, out);
      break;
    case NodeKind::Use:
      // The referenced node's own transform applies first, then the <use>'s.
      if (node.target) writeNode(*node.target, m, material, topLevel, out);
      break;
    case NodeKind::Shape:
      writeLeaf(node, m, material, topLevel, out);
      break;
    case NodeKind::Light:
      break;  // written with the lights, placed in the world (Scene::lights)
    case NodeKind::Union:
    case NodeKind::Merge:
    case NodeKind::Intersection:
    case NodeKind::Difference: {
      int operands = 0;
      for (const auto& c : node.children) operands += operandCount(*c);
      if (operands == 0) break;
      if (solid) ignoreOwnShadows_ = true;
      if (operands == 1) {
        // One operand is the operand itself (POV-Ray would warn about a one-object CSG).
        for (const auto& c : node.children) writeNode(*c, m, material, false, out);
        break;
      }
      warnCoincidentSurfaces(node, issues_);
      const bool inv = takeInverse();
      // POV-Ray's CSG keywords are Lucent's element names.
      out.open(nodeKindName(node.kind), "<" + node.element + "> " + node.loc.str());
      const bool markHere = solid && !inWrittenSolid_;
      if (solid) inWrittenSolid_ = true;
      // A union keeps every operand's surfaces, each its own object to POV-Ray as to
      // Lucent: only the solid operations share one interior (see the header).
      const std::optional<uint32_t> outer = csgInterior_;
      const bool share = node.kind != NodeKind::Union && !csgInterior_ && !inClipOrBound_ &&
                         materials_.surface(material).interior;
      if (share) csgInterior_ = material;
      for (const auto& c : node.children) writeNode(*c, Mat4(1.0), material, false, out);
      if (share) materials_.writeInteriorFor(material, out);
      csgInterior_ = outer;
      writeSolids("clipped_by", node.clip, Mat4(1.0), material, out);
      if (!isIdentity(m)) out.line(povMatrix(m));
      if (markHere) writeVisibility(out);
      if (inv) out.line("inverse");
      out.close();
      break;
    }
  }
  marks_ = outerMarks;
  ignoreOwnShadows_ = outerIgnore;
  inWrittenSolid_ = outerInSolid;
  pendingInverse_ = false;  // an inverse its subtree did not use (no object) ends with it
}

void PovGeometry::writeSolids(const char* keyword, const std::vector<std::unique_ptr<Node>>& solids,
                              const Mat4& m, uint32_t material, PovWriter& out) {
  if (solids.empty()) return;
  asOwnSolids([&] {
    out.open(keyword);
    for (const auto& c : solids) writeNode(*c, m, material, false, out);
    out.close();
  });
}

// Shapes written as solids of their own (clips, bounds, an object pattern's object): the
// flags of the object around them are not theirs.
void PovGeometry::asOwnSolids(const std::function<void()>& write) {
  const Marks marks = marks_;
  const bool ignore = ignoreOwnShadows_, inSolid = inWrittenSolid_, inverse = pendingInverse_,
             inClip = inClipOrBound_;
  inClipOrBound_ = true;
  marks_ = Marks{};
  ignoreOwnShadows_ = true;
  inWrittenSolid_ = true;
  pendingInverse_ = false;
  write();
  marks_ = marks;
  ignoreOwnShadows_ = ignore;
  inWrittenSolid_ = inSolid;
  pendingInverse_ = inverse;
  inClipOrBound_ = inClip;
}

void PovGeometry::markNode(const Node& node) {
  if (!ignoreOwnShadows_) {
    marks_.noShadow = marks_.noShadow || !node.shadows;
    marks_.noImage = marks_.noImage || !node.image;
    marks_.noReflection = marks_.noReflection || !node.reflection;
  }
  marks_.doubleIlluminate = marks_.doubleIlluminate || node.doubleIlluminate;
  if (node.interiorMaterial) marks_.interior = node.interiorMaterial;
}

void PovGeometry::writeVisibility(PovWriter& out) const {
  if (marks_.noShadow) out.line("no_shadow");
  if (marks_.noImage) out.line("no_image");
  if (marks_.noReflection) out.line("no_reflection");
}

bool PovGeometry::writesInterior(uint32_t material) {
  if (inClipOrBound_ || !marks_.interior || *marks_.interior == material) return false;
  used_[*marks_.interior] = true;
  return true;
}

std::string PovGeometry::meshName(const MeshSpec& mesh, const Node& node) {
  auto key = std::make_pair(mesh.data.get(), mesh.smooth);
  auto found = meshNames_.find(key);
  if (found != meshNames_.end()) return found->second;

  const MeshData& data = *mesh.data;
  // The normals the renderer uses (scenegraph/shapes/mesh.cpp): the file's for auto, none
  // for false, computed vertex normals for true.
  std::vector<Vec3> normals;
  if (mesh.smooth == SmoothMode::Auto) normals = data.normals;
  if (mesh.smooth == SmoothMode::True) normals = computeVertexNormals(data);
  if (normals.size() != data.positions.size()) normals.clear();
  const bool uvs = !data.uvs.empty() && data.uvs.size() == data.positions.size();

  std::string name = fmt::format("Mesh{}", meshNames_.size());
  meshNames_[key] = name;
  PovWriter& out = meshDeclarations_;
  out.line(fmt::format("// <mesh{}> {}", mesh.src.empty() ? "" : " src=\"" + mesh.src + "\"",
                       node.loc.str()));
  out.open(fmt::format("#declare {} = mesh2", name));
  out.open("vertex_vectors");
  out.line(fmt::format("{},", data.positions.size()));
  for (size_t i = 0; i < data.positions.size(); ++i)
    out.line(povVector(data.positions[i]) + (i + 1 < data.positions.size() ? "," : ""));
  out.close();
  if (!normals.empty()) {
    out.open("normal_vectors");
    out.line(fmt::format("{},", normals.size()));
    for (size_t i = 0; i < normals.size(); ++i)
      out.line(povVector(normals[i]) + (i + 1 < normals.size() ? "," : ""));
    out.close();
  }
  if (uvs) {
    out.open("uv_vectors");
    out.line(fmt::format("{},", data.uvs.size()));
    for (size_t i = 0; i < data.uvs.size(); ++i)
      out.line(fmt::format("<{}, {}>{}", povNumber(data.uvs[i].x), povNumber(data.uvs[i].y),
                           i + 1 < data.uvs.size() ? "," : ""));
    out.close();
  }
  out.open("face_indices");
  out.line(fmt::format("{},", data.triangles.size()));
  for (size_t i = 0; i < data.triangles.size(); ++i) {
    const auto& t = data.triangles[i];
    out.line(
        fmt::format("<{}, {}, {}>{}", t[0], t[1], t[2], i + 1 < data.triangles.size() ? "," : ""));
  }
  out.close();
  // A closed mesh is a solid in Lucent; POV-Ray needs an inside_vector to know its inside.
  if (data.closed) out.line("inside_vector " + povVector(kInsideVector));
  out.close();
  out.blank();
  return name;
}

namespace {

// The registry's writers write into the exporter's text through this.
class ShapeOut final : public PovShapeOut {
 public:
  ShapeOut(PovWriter& out, std::string comment, std::function<std::string(const MeshSpec&)> mesh,
           std::function<void(const std::string&)> error,
           std::function<std::string(uint32_t)> material)
      : out_(out),
        comment_(std::move(comment)),
        mesh_(std::move(mesh)),
        error_(std::move(error)),
        material_(std::move(material)) {}
  void open(std::string_view keyword) override { out_.open(keyword, comment_); }
  void line(std::string_view text) override { out_.line(text); }
  std::string number(double v) const override { return povNumber(v); }
  std::string vector(const Vec3& v) const override { return povVector(v); }
  std::string declaredMesh(const MeshSpec& mesh) override { return mesh_(mesh); }
  std::optional<std::string> function(
      const std::string& text, const std::vector<std::pair<std::string, double>>& constants,
      const std::vector<std::shared_ptr<const PigmentFunction>>& pigments,
      std::string& problem) override {
    std::optional<std::string> body =
        povFunctionText(text, constants, povNumber, problem, pigments);
    if (body) writePigmentFunctions(pigments, out_);
    return body;
  }
  void error(const std::string& message) override { error_(message); }
  std::string materialTexture(uint32_t material) override { return material_(material); }

 private:
  PovWriter& out_;
  std::string comment_;
  std::function<std::string(const MeshSpec&)> mesh_;
  std::function<void(const std::string&)> error_;
  std::function<std::string(uint32_t)> material_;
};

}  // namespace

void PovGeometry::writeShapeHead(const Node& node, const Mat4& m, uint32_t material, bool topLevel,
                                 bool& inverse, PovWriter& out) {
  std::string where = "<" + node.element + "> " + node.loc.str();
  ShapeSpec spec = *node.shape;
  if (const auto* p = std::get_if<PlaneSpec>(&spec)) {
    // An inverse plane is the plane facing the other way.
    if (inverse) {
      spec = PlaneSpec{-p->normal, -p->offset};
      p = &std::get<PlaneSpec>(spec);
      inverse = false;
    }
    // A top-level plane holding the camera is turned inside out (the same surface) unless
    // the camera is meant to be in its medium: POV-Ray would start camera rays inside it.
    const Material& mat = scene_.materials[material];
    bool medium = (mat.isTransmissive() && mat.ior != 1.0) || mat.attenuates();
    if (topLevel && !medium && cameraInsidePlane(*p, m, camera_)) {
      spec = PlaneSpec{-p->normal, -p->offset};
      where += " (turned so the camera is outside)";
    }
  }
  // A uv-mapped box: POV-Ray takes its cube map in its left-handed space, Lucent in the
  // importer's (z negated), so the box is written mirrored in z and mirrored back by its
  // first transform, which POV-Ray's (u, v) undo (Box::UVCoord works in the box's space).
  const auto* box = std::get_if<BoxSpec>(&spec);
  const bool mirrored = box && !inClipOrBound_ && uvMappedHere(material);
  if (mirrored) {
    const Vec3 lo = glm::min(box->min, box->max), hi = glm::max(box->min, box->max);
    spec = BoxSpec{Vec3(lo.x, lo.y, -hi.z), Vec3(hi.x, hi.y, -lo.z)};
  }
  // A part's own material (a blob component's): its declared texture.
  auto partMaterial = [&](uint32_t index) {
    used_[index] = true;
    if (materials_.dependsOnShape(index))
      issues_.error(node.loc, "<" + node.element +
                                  ">: a component's material with an image or a uv mapping "
                                  "cannot be written for POV-Ray");
    return "texture { " + materials_.textureName(index) + " }";
  };
  ShapeOut shapeOut(
      out, where, [&](const MeshSpec& mesh) { return meshName(mesh, node); },
      [&](const std::string& message) { issues_.error(node.loc, message); }, partMaterial);
  shapeTypeOf(spec).writePov(spec, shapeOut);
  if (mirrored) out.line("matrix <1, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0, 0>");
}

// Does the leaf's material or the interior texture written with it read (u, v)?
bool PovGeometry::uvMappedHere(uint32_t material) const {
  if (usesUvMapping(scene_.materials[material])) return true;
  return marks_.interior && usesUvMapping(scene_.materials[*marks_.interior]);
}

void PovGeometry::writeLeaf(const Node& node, const Mat4& m, uint32_t material, bool topLevel,
                            PovWriter& out) {
  bool inv = takeInverse();
  if (!node.shape) return;
  if (const auto* mesh = std::get_if<MeshSpec>(&*node.shape)) {
    if (!mesh->data || mesh->data->triangles.empty()) {
      issues_.error(node.loc, "<mesh> has no triangles; POV-Ray cannot hold an empty mesh2");
      return;
    }
  }
  const Material& mat = scene_.materials[material];
  if (!isSolid(*node.shape) && mat.isTransmissive() && mat.ior != 1.0)
    issues_.warning(node.loc, fmt::format("<{}> has no inside: Lucent passes light straight "
                                          "through it, POV-Ray refracts with ior {}",
                                          node.element, mat.ior));
  warnSmoothNormalRule(node, issues_);
  used_[material] = true;
  std::vector<ImageMapFace> faces;
  // A projected image needs no faces of its own (POV-Ray projects it as Lucent does): a box
  // whose patterns are read at (u,v) keeps its shape, which has POV-Ray's (u,v).
  const auto* image = std::get_if<ImageTexture>(&mat.texture);
  const bool projected = image && image->projection != ImageProjection::uv;
  if (!inClipOrBound_ && materials_.usesImageMap(material) &&
      !(projected && uvMappedHere(material)))
    faces = shapeTypeOf(*node.shape).povImageFaces(*node.shape);
  if (!faces.empty() && uvMappedHere(material))
    issues_.error(node.loc, "<" + node.element +
                                "> with an image on its faces and a pattern mapped at (u,v): "
                                "POV-Ray's faces written as planes have no (u,v)");
  if (!faces.empty()) {
    // Each face has its own copy of the image: the solid as the intersection of its face
    // planes, each with its own mapping. The same solid, surface and inside.
    out.open("intersection",
             "<" + node.element + "> " + node.loc.str() + " with a per-face image map");
    for (const ImageMapFace& face : faces) {
      out.open("plane");
      out.line(fmt::format("{}, {}", povVector(face.normal), povNumber(face.offset)));
      materials_.writeFor(material, face.mapping, node.element.c_str(), node.loc, out, issues_);
      if (writesInterior(material))
        materials_.writeInteriorTexture(*marks_.interior, face.mapping, node.element.c_str(),
                                        node.loc, out, issues_);
      if (marks_.doubleIlluminate) out.line("double_illuminate");
      out.close();
    }
    writeSolids("clipped_by", node.clip, Mat4(1.0), material, out);
    if (!isIdentity(m)) out.line(povMatrix(m));
    if (!inWrittenSolid_) writeVisibility(out);
    if (inv) out.line("inverse");
    out.close();
    return;
  }
  writeShapeHead(node, m, material, topLevel, inv, out);
  // POV-Ray refuses a texture in a clip or bound.
  if (!inClipOrBound_)
    materials_.writeFor(material, *node.shape, node.loc, out, issues_, csgInterior_ != material);
  if (writesInterior(material))
    materials_.writeInteriorTexture(*marks_.interior, *node.shape, node.loc, out, issues_);
  writeSolids("clipped_by", node.clip, Mat4(1.0), material, out);
  if (!isIdentity(m)) out.line(povMatrix(m));
  if (!inWrittenSolid_) writeVisibility(out);
  if (marks_.doubleIlluminate && !inClipOrBound_) out.line("double_illuminate");
  if (inv) out.line("inverse");
  out.close();
}

}  // namespace lucent
