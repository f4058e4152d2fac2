// The scene writer: settings, cameras, lights, fog, sky, materials and the node tree. The
// attributes of shapes, cameras and lights come from their tables through AttributeProbe,
// what a shape's entry reads itself from scene_writer_shapes.cpp; a value neither can hand
// back is an error at the construct.
#include "scene_writer.h"

#include "attribute_probe.h"
#include "scene_writer_out.h"
#include "xml_numbers.h"

#include "primitives/value_limits.h"
#include "scenegraph/shape_registry.h"
#include "scenegraph/shape_type.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

namespace lucent {

void XmlOut::source(const SourceLoc& loc) {
  if (loc.file.empty()) return;
  text += std::string(2 * depth, ' ') + "<!-- from " + xmlEscape(loc.str()) + " -->\n";
}

void XmlOut::open(const std::string& name, const Attributes& attributes, bool empty) {
  text += std::string(2 * depth, ' ') + "<" + name;
  for (const auto& [key, value] : attributes) text += " " + key + "=\"" + xmlEscape(value) + "\"";
  text += empty ? "/>\n" : ">\n";
  if (!empty) ++depth;
}

void XmlOut::close(const std::string& name) {
  --depth;
  text += std::string(2 * depth, ' ') + "</" + name + ">\n";
}

void cannotWrite(const SourceLoc& loc, const std::string& what) {
  throw LocatedError(loc, "cannot convert: " + what);
}

namespace {

// A rotation's rounding can leave such entries (sin(180°) times another rotation's:
// -4.5e-32 beside entries near 1). The language refuses nonzero numbers below
// kMinMagnitude; an entry that small beside the largest of its kind (below 1e-16 of it,
// under the rounding of every product it enters) is written as 0, which changes no computed
// bit that matters. Entries that are all that small (a scale of 1e-35) are refused: 0 would
// make them degenerate. `what` names them in the message ("the transform's entry").
void dropResidues(std::vector<double*> values, const SourceLoc& loc, const std::string& what) {
  double largest = 0.0;
  for (const double* v : values) largest = std::max(largest, std::abs(*v));
  for (double* v : values) {
    if (*v == 0.0 || std::abs(*v) >= kMinMagnitude) continue;
    if (std::abs(*v) < 1e-16 * largest) {
      *v = 0.0;
      continue;
    }
    cannotWrite(loc, what + " " + xmlNumber(*v) +
                         " is below the smallest magnitude the scene language reads (" +
                         xmlNumber(kMinMagnitude) + ")");
  }
}

}  // namespace

std::string transformText(const Mat4& m, const SourceLoc& loc) {
  Mat4 written = m;
  std::vector<double*> entries;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) entries.push_back(&written[c][r]);
  dropResidues(entries, loc, "the transform's entry");
  return xmlMatrix(written);
}

std::string fileReference(const std::string& resolvedPath, const std::string& folder) {
  namespace fs = std::filesystem;
  const fs::path base = fs::absolute(folder.empty() ? fs::path(".") : fs::path(folder));
  return fs::absolute(resolvedPath).lexically_normal().lexically_relative(base).generic_string();
}

namespace {

// The values a table's reader reads back from `value`, minus those equal to the same
// reader's on `plain` (the defaults), unless `all`.
template <class T, class Read>
Attributes probed(const T& value, const T& plain, Read read, const SourceLoc& loc,
                  const std::string& element, bool all) {
  AttributeProbe got, byDefault;
  T copy = value, defaults = plain;
  read(copy, got);
  read(defaults, byDefault);
  if (!got.unwritable.empty())
    cannotWrite(loc, "the <" + element + "> attribute '" + got.unwritable.front() +
                         "' cannot be written yet");
  Attributes a;
  for (const auto& [name, text] : got.values) {
    const std::string* d = byDefault.find(name);
    if (all || !d || *d != text) a.emplace_back(name, text);
  }
  return a;
}

class SceneWriter {
 public:
  SceneWriter(const Scene& scene, const WriteOptions& options) : scene_(scene), opt_(options) {}

  std::string write() {
    out_.text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out_.text += "<!-- Written by lucent convert from " + xmlEscape(scene_.file) +
                 (scene_.animation.present ? ", frame " + std::to_string(scene_.frame) : "") +
                 " -->\n<scene version=\"1\">\n";
    writeSettings();
    for (const Camera& c : scene_.cameras) writeCamera(c);
    writeFog();
    writeRainbows();
    writeSky();
    countMaterials();
    writeSharedMaterials();
    for (const auto& n : scene_.lightRoot->children) writeNode(*n);
    for (const auto& n : scene_.root->children) writeNode(*n);
    if (!scene_.defs.empty()) {
      out_.open("defs", {}, false);
      for (const auto& n : scene_.defs) writeNode(*n);
      out_.close("defs");
    }
    out_.text += "</scene>\n";
    return out_.text;
  }

  // One top-level <material id=...>, as a child of <scene>.
  std::string topLevelMaterial(const Material& m, const std::string& id) {
    return materialText(m, id, false, 1);
  }

 private:
  const Scene& scene_;
  WriteOptions opt_;
  XmlOut out_;
  std::map<uint32_t, int> uses_;           // material index: nodes that name it
  std::map<uint32_t, std::string> named_;  // shared materials: their written id
  // The nodes a <use> names: only they keep their id (the copies a <repeat> made of an
  // element with an id all carry it, and the language wants each id once).
  std::set<const Node*> targets_;

  void writeSettings() {
    const Animation& an = scene_.animation;
    if (an.present) {
      out_.text += "  <!-- every frame of this file is frame " + std::to_string(scene_.frame) +
                   " of the scene it was converted from (clock " + xmlNumber(scene_.clock) +
                   ") -->\n";
      out_.open("animation",
                {{"frames", std::to_string(an.frames)},
                 {"clock-from", xmlNumber(an.clockFrom)},
                 {"clock-to", xmlNumber(an.clockTo)},
                 {"cyclic", an.cyclic ? "true" : "false"}},
                true);
    }
    const RenderSettings& r = scene_.render;
    Attributes a{{"width", std::to_string(r.width)},        {"height", std::to_string(r.height)},
                 {"samples", std::to_string(r.samples)},    {"adaptive", xmlNumber(r.adaptive)},
                 {"max-depth", std::to_string(r.maxDepth)}, {"min-weight", xmlNumber(r.minWeight)},
                 {"background", xmlColor(r.background)},    {"ambient", xmlColor(r.ambient)}};
    if (r.adaptive > 0.0) {
      a.emplace_back("adaptive-mode",
                     r.adaptiveMode == AdaptiveMode::Corners ? "corners" : "centers");
      if (r.adaptiveMode == AdaptiveMode::Corners)
        a.emplace_back("adaptive-depth", std::to_string(r.adaptiveDepth));
    }
    if (r.epsilon) a.emplace_back("epsilon", xmlNumber(*r.epsilon));
    if (r.workingGamma.srgb) a.emplace_back("working-gamma", "srgb");
    else if (!r.workingGamma.linear())
      a.emplace_back("working-gamma", xmlNumber(r.workingGamma.power));
    out_.source(r.loc);
    out_.open("render", a, true);
  }

  void writeCamera(const Camera& c) {
    Camera plain;
    plain.type = c.type;
    Attributes a{{"type", cameraTypeName(c.type)}};
    if (!c.name.empty()) a.emplace_back("name", c.name);
    if (c.transform != Mat4(1.0)) a.emplace_back("transform", transformText(c.transform, c.loc));
    for (const CameraAttribute& attr : cameraAttributes()) {
      if (!attr.read || !attr.takenBy(c.type)) continue;
      if (attr.info.name == "image-plane") {  // a list the probe cannot read back
        if (c.imagePlane) {
          Camera::ImagePlane p = *c.imagePlane;
          dropResidues({&p.right.x, &p.right.y, &p.right.z, &p.up.x, &p.up.y, &p.up.z}, c.loc,
                       "the camera's image-plane component");
          a.emplace_back("image-plane", xmlVector(p.right) + " " + xmlVector(p.up));
        }
        continue;
      }
      if (attr.info.name == "lenses") {  // a list the probe cannot read back
        if (c.lensesX != plain.lensesX || c.lensesY != plain.lensesY)
          a.emplace_back("lenses", std::to_string(c.lensesX) + " " + std::to_string(c.lensesY));
        continue;
      }
      for (auto& kv : probed(c, plain, attr.read, c.loc, "camera", false)) a.push_back(kv);
    }
    out_.source(c.loc);
    const bool children = c.normal || c.focalBlur || !c.meshes.empty();
    out_.open("camera", a, !children);
    if (c.normal) writeNormalElement(*c.normal, c.loc, out_, opt_.folder);
    if (c.focalBlur) writeFocalBlur(*c.focalBlur);
    for (size_t k = 0; k < c.meshes.size(); ++k) writeCameraMesh(c.meshes, k);
    if (children) out_.close("camera");
  }

  // A mesh camera's faces: its lists as they are (the camera takes them in order), or
  // faces-of an earlier mesh that shares them (a screen moved 25 times is written once).
  void writeCameraMesh(const std::vector<Camera::FaceMesh>& meshes, size_t k) {
    const Camera::FaceMesh& m = meshes[k];
    if (!m.data) return;
    Attributes a;
    size_t first = 0;
    while (meshes[first].data != m.data) ++first;
    if (first < k) a.emplace_back("faces-of", std::to_string(first));
    else appendMeshLists(*m.data, a);
    if (m.transform != Mat4(1.0)) a.emplace_back("transform", transformText(m.transform, m.loc));
    out_.source(m.loc);
    out_.open("mesh", a, true);
  }

  void writeFocalBlur(const Camera::FocalBlur& b) {
    const Camera::FocalBlur plain;
    Attributes a{{"aperture", xmlNumber(b.aperture)}};
    if (b.focalPoint) a.emplace_back("focal-point", xmlVector(*b.focalPoint));
    if (b.samples != plain.samples) a.emplace_back("samples", std::to_string(b.samples));
    if (b.minSamples != plain.minSamples)
      a.emplace_back("min-samples", std::to_string(b.minSamples));
    if (b.confidence != plain.confidence) a.emplace_back("confidence", xmlNumber(b.confidence));
    if (b.variance != plain.variance) a.emplace_back("variance", xmlNumber(b.variance));
    out_.source(b.loc);
    out_.open("focal-blur", a, true);
  }

  Attributes lightAttributesOf(const Light& l) {
    Light plain;
    plain.type = l.type;
    Attributes a{{"type", std::string(lightTypeInfo(l.type).name)}};
    for (const LightAttribute& attr : lightAttributes()) {
      if (!attr.read || !attr.takenBy(l.type)) continue;
      const std::string& name = attr.info.name;
      // What the table's readers compute rather than store: the grid of samples (a list),
      // adaptive (absent or a level), an area light's cone (present when any of its
      // attributes is), look-at (written as the direction).
      if (name == "look-at") continue;
      if (name == "samples") {
        a.emplace_back("samples", std::to_string(l.samplesU) + " " + std::to_string(l.samplesV));
        continue;
      }
      if (name == "adaptive") {
        if (l.adaptive) a.emplace_back("adaptive", std::to_string(*l.adaptive));
        continue;
      }
      const bool coneAttribute =
          name == "direction" || name == "angle" || name == "inner" || name == "cone";
      if (l.type == LightType::Area && coneAttribute && !l.cone) continue;
      for (auto& kv : probed(l, plain, attr.read, l.loc, "light", coneAttribute)) a.push_back(kv);
    }
    return a;
  }

  void writeFog() {
    for (const Fog& f : scene_.fogs) {
      Attributes a{{"type", f.type == FogType::Ground ? "ground" : "constant"},
                   {"color", xmlColor(f.color)},
                   {"distance", xmlNumber(f.distance)},
                   {"filter", xmlNumber(f.filter)},
                   {"transmit", xmlNumber(f.transmit)}};
      if (f.type == FogType::Ground) {
        a.emplace_back("offset", xmlNumber(f.offset));
        a.emplace_back("altitude", xmlNumber(f.altitude));
        a.emplace_back("up", xmlVector(f.up));
      }
      if (f.turbulence) {
        const FogTurbulence& t = *f.turbulence;
        a.emplace_back("turbulence", xmlVector(t.strength));
        a.emplace_back("octaves", std::to_string(t.octaves));
        a.emplace_back("omega", xmlNumber(t.omega));
        a.emplace_back("lambda", xmlNumber(t.lambda));
        a.emplace_back("turb-depth", xmlNumber(t.depth));
        a.emplace_back("noise-generator", std::to_string(t.noiseGenerator));
        if (t.noiseFromWorld != Mat4(1.0))
          a.emplace_back("transform", xmlMatrix(glm::inverse(t.noiseFromWorld)));
      }
      out_.source(f.loc);
      out_.open("fog", a, true);
    }
  }

  void writeRainbows() {
    for (const Rainbow& r : scene_.rainbows) {
      const Attributes a{
          {"direction", xmlVector(r.direction)}, {"up", xmlVector(r.up)},
          {"angle", xmlNumber(r.angle)},         {"width", xmlNumber(r.width)},
          {"distance", xmlNumber(r.distance)},   {"jitter", xmlNumber(r.jitter)},
          {"arc-angle", xmlNumber(r.arcAngle)},  {"falloff-angle", xmlNumber(r.falloffAngle)}};
      out_.source(r.loc);
      out_.open("rainbow", a, false);
      writeColorMap(r.map, out_);
      out_.close("rainbow");
    }
  }

  void writeSky() {
    if (!scene_.sky) return;
    const Sky& s = *scene_.sky;
    Attributes a;
    if (s.skyFromWorld != Mat4(1.0))
      a.emplace_back("transform", transformText(glm::inverse(s.skyFromWorld), s.loc));
    if (s.layering == SkyLayering::pov36) a.emplace_back("layering", "pov-3.6");
    out_.source(s.loc);
    out_.open("sky", a, false);
    for (const Texture& layer : s.layers) writeTexture(layer, s.loc, out_, "");
    out_.close("sky");
  }

  void count(const Node& n) {
    if (n.material) ++uses_[*n.material];
    // An interior material is named by id only: written once, shared.
    if (n.interiorMaterial) uses_[*n.interiorMaterial] += 2;
    // So is a blob component's.
    if (const auto* blob = n.shape ? std::get_if<BlobSpec>(&*n.shape) : nullptr)
      for (const auto& m : blob->componentMaterials)
        if (m) uses_[*m] += 2;
    if (n.kind == NodeKind::Use && n.target) targets_.insert(n.target);
    for (const auto& c : n.children) count(*c);
    for (const auto& c : n.clip) count(*c);
    for (const auto& c : n.bound) count(*c);
    if (const Node* through = projectedThrough(n)) count(*through);
  }
  void countMaterials() {
    count(*scene_.root);
    count(*scene_.lightRoot);
    // A <defs> child keeps its id whether or not a <use> names it (the language asks for one).
    for (const auto& d : scene_.defs) {
      count(*d);
      targets_.insert(d.get());
    }
  }

  // <material id=... default=...>...</material> with its children, or inline without id.
  std::string materialText(const Material& m, const std::string& id, bool isDefault, int depth) {
    Attributes a;
    if (!id.empty()) a.emplace_back("id", id);
    if (isDefault) a.emplace_back("default", "true");
    for (auto& kv : materialAttributes(m)) a.push_back(kv);
    XmlOut children;
    children.depth = depth + 1;
    writeMaterialChildren(m, children, opt_.folder);
    XmlOut text;
    text.depth = depth;
    text.source(m.loc);
    text.open("material", a, children.text.empty());
    if (children.text.empty()) return text.text;
    text.text += children.text;
    text.close("material");
    return text.text;
  }

  void writeMaterial(const Material& m, const std::string& id, bool isDefault = false) {
    out_.text += materialText(m, id, isDefault, out_.depth);
  }

  // Materials named by more than one node are written once with an id; so is the default
  // material (index 0) when the scene made one of its own (default="true").
  void writeSharedMaterials() {
    const Material& builtIn = Material::defaultMaterial();
    const Material& first = scene_.materials.front();
    if (materialText(first, "", false, 0) != materialText(builtIn, "", false, 0) ||
        first.id != builtIn.id) {
      named_[0] = first.id.empty() || first.id == builtIn.id ? "default-material" : first.id;
      writeMaterial(first, named_[0], true);
    }
    for (const auto& [index, n] : uses_) {
      if (n < 2 || index == 0) continue;
      const Material& m = scene_.materials.at(index);
      const bool ownId = !m.id.empty() && m.id != builtIn.id;
      named_[index] = ownId ? m.id : "material-" + std::to_string(index);
      writeMaterial(m, named_[index]);
    }
  }

  // The shape's attributes, from its fields through the probe and, for what the entry's
  // finish() reads itself, from ownShapeText; its children (blob components, an
  // isosurface's parameters) into `children`.
  Attributes shapeAttributes(const Node& n, std::vector<OwnShapeChild>& children) {
    const std::optional<OwnShapeText> own = ownShapeText(*n.shape, n.loc, opt_.folder);
    if (own) children = own->children;
    return std::visit(
        [&](const auto& spec) {
          using S = std::decay_t<decltype(spec)>;
          const ShapeEntry<S> entry = shapeEntry<S>();
          auto written = [](const Attributes& a, const std::string& name) {
            return std::any_of(a.begin(), a.end(), [&](const auto& w) { return w.first == name; });
          };
          Attributes a;
          for (const Field<S>& f : entry.fields) {
            if (f.read) {
              for (auto& kv : probed(spec, spec, f.read, n.loc, entry.element, true))
                a.push_back(kv);
              continue;
            }
            if (!own)
              cannotWrite(n.loc, "the <" + std::string(entry.element) + "> attribute '" +
                                     f.info.name + "' cannot be written yet");
            // Optional attributes the parameters do not hold (a mesh's normals) are absent.
            for (const auto& kv : own->attributes)
              if (kv.first == f.info.name) a.push_back(kv);
          }
          if (own)
            for (const auto& kv : own->attributes)
              if (!written(a, kv.first)) a.push_back(kv);
          // What an entry's finish() reads itself (child elements, attributes read together)
          // must be among what was written.
          if (entry.finish) {
            AttributeProbe rest;
            S copy = spec;
            entry.finish(copy, rest);
            for (const auto& kv : rest.values)
              if (!written(a, kv.first)) rest.unwritable.push_back(kv.first);
            for (const std::string& name : rest.unwritable) {
              const bool handled = own && std::find(own->handled.begin(), own->handled.end(),
                                                    name) != own->handled.end();
              if (!handled && !written(a, name))
                cannotWrite(n.loc, "the <" + std::string(entry.element) + "> attribute or child '" +
                                       name + "' cannot be written yet");
            }
          }
          return a;
        },
        *n.shape);
  }

  void writeNode(const Node& n) {
    Attributes a;
    if (!n.id.empty() && targets_.count(&n)) a.emplace_back("id", n.id);
    std::string element = n.element;
    std::vector<OwnShapeChild> shapeChildren;
    if (n.kind == NodeKind::Shape) {
      // The registry's element, not the name the node was read as (a POV-Ray quartic is a
      // <poly>).
      element = shapeElementName(*n.shape);
      for (auto& kv : shapeAttributes(n, shapeChildren)) a.push_back(kv);
      // A blob component's own material, by id: its children are the components in order.
      if (const auto* blob = std::get_if<BlobSpec>(&*n.shape))
        for (size_t k = 0; k < blob->componentMaterials.size() && k < shapeChildren.size(); ++k)
          if (blob->componentMaterials[k])
            shapeChildren[k].attributes.emplace_back("material",
                                                     named_.at(*blob->componentMaterials[k]));
    } else if (n.kind == NodeKind::Use) {
      if (!n.target || n.target->id.empty())
        cannotWrite(n.loc, "a <use> whose target has no id cannot be written");
      a.emplace_back("ref", n.target->id);
    } else if (n.kind == NodeKind::Light) {
      element = "light";
      for (auto& kv : lightAttributesOf(*n.light)) a.push_back(kv);
    } else if (n.lightGroup) {
      element = "light-group";
      if (n.globalLights) a.emplace_back("global-lights", "true");
    } else {
      element = nodeKindName(n.kind);
    }
    if (n.parentFromNode != Mat4(1.0))
      a.emplace_back("transform", transformText(n.parentFromNode, n.loc));
    if (!n.shadows) a.emplace_back("shadows", "false");
    if (!n.image) a.emplace_back("image", "false");
    if (!n.reflection) a.emplace_back("reflection", "false");
    if (n.doubleIlluminate) a.emplace_back("double-illuminate", "true");
    if (n.inverse) a.emplace_back("inverse", "true");
    const bool inlineMaterial = n.material && !named_.count(*n.material);
    if (n.material && !inlineMaterial) a.emplace_back("material", named_.at(*n.material));
    if (n.interiorMaterial) a.emplace_back("interior-material", named_.at(*n.interiorMaterial));
    out_.source(n.loc);
    const Node* through = projectedThrough(n);
    const bool empty = !inlineMaterial && n.children.empty() && shapeChildren.empty() &&
                       n.clip.empty() && n.bound.empty() && !through;
    out_.open(element, a, empty);
    if (empty) return;
    // A shape's parameters first: a local <param> is visible in the whole element.
    for (const OwnShapeChild& c : shapeChildren)
      if (c.element == "param") out_.open(c.element, c.attributes, true);
    if (inlineMaterial) writeMaterial(scene_.materials.at(*n.material), "");
    for (const OwnShapeChild& c : shapeChildren) {
      if (c.element == "param") continue;
      out_.open(c.element, c.attributes, !c.body);
      if (!c.body) continue;
      c.body(out_);
      out_.close(c.element);
    }
    for (const auto& c : n.children) writeNode(*c);
    writeSolids("clip", n.clip);
    writeSolids("bound", n.bound);
    if (through) writeSolids("projected-through", through->children);
    out_.close(element);
  }

  // A light's <projected-through> group, or null.
  static const Node* projectedThrough(const Node& n) {
    return n.kind == NodeKind::Light && n.light ? n.light->projectedThrough.get() : nullptr;
  }

  // A node's <clip> or <bound>, its solids in the node's frame, or a light's
  // <projected-through>, its objects in the light's frame.
  void writeSolids(const char* element, const std::vector<std::unique_ptr<Node>>& solids) {
    if (solids.empty()) return;
    out_.open(element, {}, false);
    for (const auto& c : solids) writeNode(*c);
    out_.close(element);
  }
};

}  // namespace

std::string writeSceneXml(const Scene& scene, const WriteOptions& options) {
  return SceneWriter(scene, options).write();
}

std::string writeMaterialXml(const Material& material, const std::string& id,
                             const WriteOptions& options) {
  const Scene none;
  return SceneWriter(none, options).topLevelMaterial(material, id);
}

}  // namespace lucent
