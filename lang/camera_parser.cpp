// <camera> (contract, "<camera>"), read through the camera table (scenegraph/camera.h): its
// type names, the attributes each type takes, their readers and the checks between them.
// This file adds what only the scene language can read: the type first (it decides the
// other attributes), a name unique among the scene's cameras, the transform's syntax, and
// the message for an attribute of another type, which names the types it belongs to.
#include "element_input.h"
#include "element_parsers.h"
#include "pattern_parser.h"

#include "scenegraph/shapes/mesh_lists.h"

namespace lucent {

namespace {

// The names of type="..." (scenegraph/camera.cpp's table).
std::vector<std::pair<std::string_view, CameraType>> typeChoices() {
  std::vector<std::pair<std::string_view, CameraType>> choices;
  for (const CameraTypeInfo& t : cameraTypes()) choices.emplace_back(t.name, t.type);
  return choices;
}

// The attributes a camera of type t takes.
std::vector<std::string_view> attributesOf(CameraType t) {
  std::vector<std::string_view> names;
  for (const CameraAttribute& a : cameraAttributes())
    if (a.takenBy(t)) names.push_back(a.info.name);
  return names;
}

// "belongs to orthographic cameras; this camera is pinhole (set type="orthographic")" for
// an attribute of other types; "" for one no type takes.
std::string otherTypesAttribute(std::string_view attr, CameraType type) {
  std::vector<std::string> owners;
  for (const CameraAttribute& a : cameraAttributes())
    if (a.info.name == attr)
      for (const CameraTypeInfo& t : cameraTypes())
        if (a.takenBy(t.type)) owners.emplace_back(t.name);
  if (owners.empty()) return {};
  std::string list = owners[0];
  for (size_t i = 1; i < owners.size(); ++i)
    list += (i + 1 == owners.size() ? " and " : ", ") + owners[i];
  return "belongs to " + list + " cameras; this camera is " + cameraTypeName(type) +
         " (set type=\"" + owners[0] + "\")";
}

void readName(ElementReader& r, Camera& cam) {
  auto name = r.text("name");
  if (!name) return;
  ParseContext& ctx = r.ctx();
  if (!isValidId(*name))
    r.attrError("name",
                "a camera name must be non-empty and contain no spaces, got '" + *name + "'");
  else if (auto [it, inserted] = ctx.cameraNames.try_emplace(*name, cam.loc); !inserted)
    r.attrError("name",
                "a camera named '" + *name + "' already exists (at " + it->second.str() + ")");
  else cam.name = *name;
}

// <focal-blur>: POV-Ray's focal blur (render/focal_blur.h).
Camera::FocalBlur parseFocalBlur(ElementReader& r) {
  Camera::FocalBlur blur;
  blur.loc = r.loc();
  r.checkAttributes(
      {"aperture", "focal-point", "samples", "min-samples", "confidence", "variance"});
  if (!r.has("aperture"))
    r.error("<focal-blur> needs 'aperture', the lens disc's diameter (world units)");
  blur.aperture = r.number("aperture", 1.0, NumberRule::positive());
  if (r.has("focal-point")) blur.focalPoint = r.vector("focal-point", Vec3(0.0));
  blur.samples =
      static_cast<int>(r.integer("samples", blur.samples, 1, Camera::kMaxFocalBlurSamples));
  blur.minSamples =
      static_cast<int>(r.integer("min-samples", blur.minSamples, 0, Camera::kMaxFocalBlurSamples));
  if (blur.minSamples > blur.samples)
    r.attrError("min-samples", "'min-samples' (" + std::to_string(blur.minSamples) +
                                   ") must not exceed 'samples' (" + std::to_string(blur.samples) +
                                   ")");
  blur.confidence = r.number(
      "confidence", blur.confidence,
      NumberRule::between(0.0, 1.0, "a number between 0 and 1 (both excluded)", true, true));
  blur.variance =
      r.number("variance", blur.variance, NumberRule::between(0.0, 1.0, "a number from 0 to 1"));
  return blur;
}

// A mesh camera's <mesh>: its faces as written, or faces-of="K" those of the camera's mesh
// K (counted from 0) already read, and its transform (render/mesh_camera.h).
Camera::FaceMesh parseCameraMesh(ElementReader& r, const std::vector<Camera::FaceMesh>& before) {
  Camera::FaceMesh m;
  m.loc = r.loc();
  r.checkAttributes({"positions", "indices", "normals", "uvs", "transform", "faces-of"});
  if (r.has("faces-of")) {
    for (const char* list : {"positions", "indices", "normals", "uvs"})
      if (r.has(list))
        r.attrError(list, "a <mesh> with faces-of takes the faces of another: no lists of its own");
    if (before.empty()) {
      r.attrError("faces-of", "faces-of names an earlier <mesh> of the camera; this is the first");
    } else {
      const auto k = static_cast<size_t>(
          r.integer("faces-of", 0, 0, static_cast<long long>(before.size()) - 1));
      m.data = before[std::min(k, before.size() - 1)].data;
    }
  } else {
    ElementInput in(r);
    m.data = readMeshLists(in);
  }
  m.transform = r.transform("transform");
  return m;
}

}  // namespace

void parseCamera(ElementReader& r) {
  ParseContext& ctx = r.ctx();
  Camera cam;
  cam.loc = r.loc();
  cam.type = r.choice("type", CameraType::Pinhole, typeChoices());
  r.checkAttributes(attributesOf(cam.type),
                    [&](std::string_view attr) { return otherTypesAttribute(attr, cam.type); });

  // In the table's order; the attributes without a reader are the language's own.
  ElementInput in(r);
  for (const CameraAttribute& a : cameraAttributes()) {
    if (!a.takenBy(cam.type)) continue;
    if (a.read) a.read(cam, in);
    else if (a.info.name == "name") readName(r, cam);
    else if (a.info.name == "transform") cam.transform = r.transform("transform");
  }
  checkCamera(cam, in);

  // <normal>: POV-Ray's camera normal, which bends the primary rays (render/camera_normal.h);
  // <focal-blur>: POV-Ray's focal blur (render/focal_blur.h). One of each at most.
  std::optional<SourceLoc> normalLoc, blurLoc;
  const bool mesh = cam.type == CameraType::Mesh;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader child(ctx, r.file(), n);
    const std::string_view name = n.name();
    if (mesh && name == "mesh") {
      cam.meshes.push_back(parseCameraMesh(child, cam.meshes));
    } else if (mesh) {
      child.error("a mesh camera takes <mesh> children (the faces its rays start on), got <" +
                  std::string(name) + ">");
    } else if (name != "normal" && name != "focal-blur") {
      child.error("<camera> takes a <normal> (POV-Ray's camera normal) and a <focal-blur>, got <" +
                  std::string(name) + ">");
    } else if (name == "normal" && normalLoc) {
      child.error("<camera> holds one <normal> at most; the first is at " + normalLoc->str());
    } else if (name == "focal-blur" && blurLoc) {
      child.error("<camera> holds one <focal-blur> at most; the first is at " + blurLoc->str());
    } else if (name == "normal") {
      normalLoc = child.loc();
      cam.normal = parseNormal(child);
      if (cam.normal->bendInWorld)
        child.attrError("bend-space",
                        "bend-space is for a material's normal: a camera's normal bends the "
                        "ray's direction");
    } else {
      blurLoc = child.loc();
      if (cam.type == CameraType::ThinLens)
        child.error(
            "a thin-lens camera has its own lens (focal-length, f-stop, focus-distance): "
            "<focal-blur> is for the other camera types");
      cam.focalBlur = parseFocalBlur(child);
    }
  });
  if (mesh && cam.meshes.empty())
    r.error("a mesh camera needs at least one <mesh> child (the faces its rays start on)");
  else if (mesh && cam.distribution == 0 &&
           static_cast<size_t>(cam.raysPerPixel) > cam.meshes.size())
    r.attrError("rays-per-pixel",
                "a mesh camera of distribution 0 takes ray r of each sample from mesh r: "
                "rays-per-pixel (" +
                    std::to_string(cam.raysPerPixel) + ") must not exceed its " +
                    std::to_string(cam.meshes.size()) + " meshes");
  ctx.scene.cameras.push_back(std::move(cam));
}

}  // namespace lucent
