// Objects: the simple shapes, CSG, `object { Identifier ... }`, light sources as objects,
// and the object modifiers (transforms, texture, interior, flags).
#include "read_support.h"
#include "scene_reader.h"

#include "scenegraph/shape_registry.h"

#include <algorithm>
#include <cmath>

namespace lucent::sdl {

namespace {

NodeKind csgKind(std::string_view word) {
  if (word == "union") return NodeKind::Union;
  if (word == "merge") return NodeKind::Merge;
  if (word == "intersection") return NodeKind::Intersection;
  if (word == "difference") return NodeKind::Difference;
  return NodeKind::Group;
}

// POV-Ray's height fields and lathes have no walls, floor or discs (the importer sets
// `open`), but an intersection, a difference, a merge or a clip asks their inside, which an
// open Lucent shape has not: there they stay closed, as Lucent's solid. The messages of
// those closed again, at each.
// Whether the object holds an open height field or lathe (only then is it changed, so a
// declared object's children stay shared).
bool opensInCsg(const PovObject& o) {
  if (o.shape) {
    if (auto* h = std::get_if<HeightFieldSpec>(&*o.shape); h && h->open) return true;
    if (auto* l = std::get_if<LatheSpec>(&*o.shape); l && l->open) return true;
  }
  for (const PovObject& c : *o.children)
    if (opensInCsg(c)) return true;
  return false;
}

void closeForCsg(PovObject& o, std::vector<std::pair<SourceLoc, std::string>>& closed) {
  if (!opensInCsg(o)) return;
  if (o.shape) {
    if (auto* h = std::get_if<HeightFieldSpec>(&o.shape.edit()); h && h->open) {
      h->open = false;
      closed.emplace_back(o.loc,
                          "in an intersection, difference, merge or clip Lucent's height field "
                          "is a solid closed by walls and a floor at the water level; "
                          "POV-Ray's has none (seen from below or beside, they differ)");
    }
    if (auto* l = std::get_if<LatheSpec>(&o.shape.edit()); l && l->open) {
      l->open = false;
      closed.emplace_back(o.loc,
                          "in an intersection, difference, merge or clip Lucent's lathe is a "
                          "solid, its curve closed with discs to the axis; POV-Ray "
                          "leaves it open");
    }
  }
  for (PovObject& c : o.children.edit()) closeForCsg(c, closed);
}

// POV-Ray's patch objects (no inside, no inverse: triangles, bicubic patches, parametrics
// and meshes without inside_vector), also as parts of a CSG, which takes its parts' flag:
// the first such object in o, or null. POV-Ray refuses them in clipped_by and bounded_by.
const PovObject* patchIn(const PovObject& o) {
  if (o.shape && !isSolid(*o.shape) &&
      (std::holds_alternative<TriangleSpec>(*o.shape) ||
       std::holds_alternative<BicubicPatchSpec>(*o.shape) ||
       std::holds_alternative<ParametricSpec>(*o.shape) ||
       std::holds_alternative<MeshSpec>(*o.shape)))
    return &o;
  for (const PovObject& c : *o.children)
    if (const PovObject* p = patchIn(c)) return p;
  return nullptr;
}

}  // namespace

bool SceneReader::isObjectKeyword(const Token& t) const {
  if (t.kind != TokenKind::Keyword) return false;
  const std::string_view w = t.text();
  return isShapeKeyword(w) || csgKind(w) != NodeKind::Group || w == "object" ||
         w == "light_source" || w == "light_group";
}

PovObject SceneReader::readObject(const Token& t, TokenStream& in) {
  PovObject o;
  o.keyword = std::string(t.text());
  o.loc = t.loc();
  // Objects within objects recurse on the C++ stack: bounded, as the core bounds expressions.
  if (objectDepth_ >= kMaxObjectDepth)
    in.error(t, "objects nested more than " + std::to_string(kMaxObjectDepth) + " deep");
  struct Depth {
    int& d;
    explicit Depth(int& depth) : d(++depth) {}
    ~Depth() { --d; }
  } depth(objectDepth_);
  if (o.keyword == "light_source") {
    o.kind = NodeKind::Light;
    o.light = readLight(o.loc, in);
    return o;
  }
  in.expect("{");
  if (o.keyword != "object" && o.keyword != "light_group") {
    // POV-Ray's `SHAPE { IDENTIFIER modifiers }` (its Parse_Object_Id): a copy of the
    // declared object, whatever its kind, as `object { IDENTIFIER ... }`.
    if (const auto* item = use<ObjectItem>(in.peek(), in)) {
      in.next();
      o = item->object;
      readObjectModifiers(o, in, t.text());
      return o;
    }
  }
  if (o.keyword == "object") {
    const Token first = in.next();
    const auto* item = use<ObjectItem>(first, in);
    if (item) {
      o = item->object;
    } else if (const auto* refused = use<RefusedItem>(first, in)) {
      // Its refusal is reported (use): the scene will not render, reading goes on.
      (void)refused;
    } else if (isObjectKeyword(first)) {
      o = readObject(first, in);
    } else {
      in.error(first, "an object identifier or an object expected after 'object {', not " +
                          first.describe());
    }
  } else if (o.keyword == "light_group") {
    readLightGroup(o, in);
    return o;
  } else if (csgKind(o.keyword) != NodeKind::Group) {
    o.kind = csgKind(o.keyword);
    readChildren(o, in);
    if (o.kind != NodeKind::Union) {
      std::vector<std::pair<SourceLoc, std::string>> closed;
      for (PovObject& c : o.children.edit()) closeForCsg(c, closed);
      for (const auto& [loc, message] : closed) warn(in, loc, message);
    }
  } else {
    readShape(o, in);
  }
  readObjectModifiers(o, in);
  return o;
}

// POV-Ray's Parse_Object also takes a declared object written bare (`union { sphere {..}
// A }`, `bounded_by { B }`, `A` at the top level): a copy of it, as `object { A }`.
bool SceneReader::startsObject(const Token& t) {
  return isObjectKeyword(t) || dynamic_cast<const ObjectItem*>(itemOf(t)) != nullptr;
}

PovObject SceneReader::readObjectOrCopy(const Token& t, TokenStream& in) {
  if (const auto* item = use<ObjectItem>(t, in)) return item->object;
  return readObject(t, in);
}

// The objects of a CSG operation or a light group, up to the first modifier.
void SceneReader::readChildren(PovObject& o, TokenStream& in) {
  while (startsObject(in.peek())) {
    const Token child = in.next();
    o.children.edit().push_back(readObjectOrCopy(child, in));
    // Objects built of declared objects grow without reading deeper (a loop that puts the
    // last union in the next): their depth and size are bounded as they are composed.
    const PovObject& c = o.children->back();
    o.depth = std::max(o.depth, c.depth + 1);
    o.nodes += c.nodes;
    if (o.depth > kMaxObjectDepth)
      in.error(child, "objects nested more than " + std::to_string(kMaxObjectDepth) + " deep");
    if (o.nodes > kMaxObjectNodes)
      in.error(child, "an object of more than " + std::to_string(kMaxObjectNodes) +
                          " objects (the limit of one object's size)");
  }
}

// light_group { objects and light sources, then transforms and global_lights }: POV-Ray
// takes no other modifier there (scenegraph/light_group.h has what it lights).
void SceneReader::readLightGroup(PovObject& o, TokenStream& in) {
  o.kind = NodeKind::Group;
  o.lightGroup = true;
  readChildren(o, in);
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return;
    if (readTransform(t, in, o.transform)) continue;
    if (isWord(t, "global_lights")) {
      o.globalLights = optionalBool(in);
      continue;
    }
    if (isWord(t, "photons")) unsupported(t, in, true, &o);
    else
      in.error(t, "a transform or global_lights expected in light_group, not " + t.describe() +
                      " (POV-Ray takes no other modifier there)");
  }
}

// `written`: the keyword of the block when it is not the object's own (`union { A`).
void SceneReader::readObjectModifiers(PovObject& o, TokenStream& in, std::string_view written) {
  const std::string block(written.empty() ? std::string_view(o.keyword) : written);
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) {
      promoteFinishIor(o);
      return;
    }
    if (readObjectModifier(t, o, in)) continue;
    if (startsObject(t))
      in.error(t, "an object where the modifiers of " + block +
                      " are read (POV-Ray: \"No "
                      "matching } in '" +
                      block + "'\"; in '" + block + " { IDENTIFIER' " +
                      "the identifier is the copied object, modifiers follow: write object { " +
                      "IDENTIFIER } to make it an operand)");
    if (t.kind != TokenKind::Keyword)
      in.error(t, "unexpected " + t.describe() + " in " + o.keyword);
    unsupported(t, in, true, &o);
  }
}

// POV-Ray's post-processing at the end of each object: a plain texture's `finish { ior }`
// becomes the object's interior's ior (an interior made for it if it has none).
void SceneReader::promoteFinishIor(PovObject& o) {
  if (!o.texture || o.texture->mapped() || !o.texture->finish.ior) return;
  if (!o.interior) o.interior = PovInterior{};
  o.interior->ior = *o.texture->finish.ior;
}

bool SceneReader::readObjectModifier(const Token& t, PovObject& o, TokenStream& in) {
  if (readTransform(t, in, o.transform)) return true;
  if (t.kind != TokenKind::Keyword) return false;
  const std::string_view w = t.text();
  // What is written now follows only the transforms written after it: carried back by
  // the inverse of the object's transforms so far (PovObject::texture). After the object's
  // uv_mapping its textures lie in (u, v) space, where its transforms do not reach.
  const PovTransform backToObject = o.uvMapping ? PovTransform{} : o.transform.inverse();
  if (w == "pigment" || w == "normal" || w == "finish" || w == "texture") {
    if (w == "texture" && o.texture) {
      // A texture { } on an object that has one (from any block) is a layer over it.
      PovTexture top = readTexture(in, defaultTexture());
      top.transform(backToObject);
      if (o.uvMapping) mapAtUv(top, true);
      o.texture = layerOver(std::move(o.texture.edit()), std::move(top), t.loc(), in);
      return true;
    }
    if (!o.texture) {
      o.texture = defaultTexture();
      o.texture.edit().transform(backToObject);
      o.textureLoc = t.loc();
    }
    // A block continues the object's own pigment, normal or finish, as POV-Ray's does
    // (the default texture's when the object had none): moved back to the object's
    // current space to be read on, then carried back again.
    const PovTransform here = o.uvMapping ? PovTransform{} : o.transform;
    if (w != "texture") o.texture.edit().name.clear();  // a declared texture, changed
    if (w == "pigment") {
      PovPigment start = o.texture->pigment;
      start.transform = start.transform.then(here);
      PovPigment& pigment = o.texture.edit().pigment;
      pigment = readPigment(in, start);
      pigment.transform = pigment.transform.then(backToObject);
    } else if (w == "normal") {
      std::optional<PovNormal> start = o.texture->normal;
      if (start) start->transform = start->transform.then(here);
      std::optional<PovNormal>& normal = o.texture.edit().normal;
      normal = readNormal(in, start ? &*start : nullptr);
      normal->transform = normal->transform.then(backToObject);
    } else if (w == "finish") {
      o.texture.edit().finish = readFinish(in, o.texture->finish);
    } else {
      o.texture = readTexture(in, defaultTexture());
      o.texture.edit().transform(backToObject);
      o.textureLoc = t.loc();
    }
    if (o.uvMapping) mapAtUv(o.texture.edit(), true);
  } else if (w == "uv_mapping") {
    // POV-Ray's object flag: the textures given to the object after it are read at the
    // shape's (u, v, 0), placed by their own transforms (the object's leave them).
    if (o.texture) in.error(t, "uv_mapping must be specified before texture (POV-Ray's error)");
    o.uvMapping = true;
    // The flag is the whole object's: a mesh's triangle textures (the meshes of its
    // textures, splitByTexture) are read at (u, v) too.
    if (o.kind == NodeKind::Union && (o.keyword == "mesh" || o.keyword == "mesh2"))
      for (PovObject& part : o.children.edit())
        if (part.texture) mapAtUv(part.texture.edit(), true);
  } else if (w == "interior") {
    o.interior = readInterior(in, o.interior ? *o.interior : PovInterior{});
  } else if (w == "material") {
    const PovMaterial m = readMaterial(in);
    if (m.texture) {
      o.texture = *m.texture;
      o.texture.edit().transform(backToObject);
      o.textureLoc = t.loc();
    }
    if (m.interiorTexture) {
      o.interiorTexture = *m.interiorTexture;
      o.interiorTexture.edit().transform(backToObject);
      o.interiorTextureLoc = t.loc();
    }
    if (m.interior) o.interior = m.interior;
  } else if (w == "interior_texture") {
    // POV-Ray's interior_texture replaces a former one, layered only by its own blocks.
    o.interiorTexture = readTexture(in, defaultTexture());
    o.interiorTexture.edit().transform(backToObject);
    o.interiorTextureLoc = t.loc();
  } else if (w == "no_shadow") {
    o.noShadow = true;
  } else if (w == "no_image") {
    o.noImage = optionalBool(in);
  } else if (w == "no_reflection") {
    o.noReflection = optionalBool(in);
  } else if (w == "no_radiosity") {
    optionalBool(in);  // Lucent traces no radiosity rays: nothing to hide from
  } else if (w == "double_illuminate") {
    o.doubleIlluminate = optionalBool(in);
  } else if (w == "hollow") {
    o.hollow = optionalBool(in);  // the material's hollow (fog goes on inside)
  } else if (w == "inverse") {
    o.inverse = !o.inverse;
  } else if (w == "sturm" || w == "hierarchy") {
    optionalBool(in);  // Lucent's root finding and bounding need no choice
  } else if (w == "open") {
    const bool open = optionalBool(in);
    if (o.shape && std::holds_alternative<CylinderSpec>(*o.shape))
      std::get<CylinderSpec>(o.shape.edit()).open = open;
    else if (o.shape && std::holds_alternative<ConeSpec>(*o.shape))
      std::get<ConeSpec>(o.shape.edit()).open = open;
    else if (o.shape && std::holds_alternative<IsosurfaceSpec>(*o.shape))
      std::get<IsosurfaceSpec>(o.shape.edit()).open = open;
    else if (o.shape && std::holds_alternative<SorSpec>(*o.shape))
      std::get<SorSpec>(o.shape.edit()).open = open;
    else if (o.shape && std::holds_alternative<PrismSpec>(*o.shape))
      std::get<PrismSpec>(o.shape.edit()).open = open;
    else in.error(t, "'open' is for a cylinder, cone, sor, prism or isosurface, not " + o.keyword);
  } else if (w == "clipped_by" || w == "bounded_by") {
    readClipOrBound(t, o, in);
  } else {
    return false;
  }
  return true;
}

// clipped_by { objects transforms } or bounded_by { ... } (the keyword read): the objects,
// moved by the transforms written after them, carried back into the object's own space
// so that the object's later transforms move them with it (as POV-Ray transforms an
// object's clip and bounds with it). clipped_by { bounded_by } takes the bounds as the
// clip, bounded_by { clipped_by } the reverse, with POV-Ray's errors.
void SceneReader::readClipOrBound(const Token& t, PovObject& o, TokenStream& in) {
  const bool clip = isWord(t, "clipped_by");
  std::vector<PovObject>& mine = clip ? o.clip : o.bound;
  std::vector<PovObject>& other = clip ? o.bound : o.clip;
  in.expect("{");
  if (o.boundIsClip && !mine.empty())
    in.error(t, std::string("cannot add ") + (clip ? "clips" : "bounds") +
                    " after linking bounds and clips");
  if (isWord(in.peek(), clip ? "bounded_by" : "clipped_by")) {
    const Token link = in.next();
    if (!mine.empty())
      in.error(link, std::string("cannot link ") +
                         (clip ? "bounds with previous clips" : "clips with previous bounds"));
    mine = other;
    o.boundIsClip = true;
    in.expect("}");
    return;
  }
  const PovTransform backToObject = o.transform.inverse();
  std::vector<PovObject> objects;
  while (startsObject(in.peek())) {
    const Token first = in.next();
    objects.push_back(readObjectOrCopy(first, in));
    if (objects.back().kind == NodeKind::Light)
      in.error(first,
               std::string("a light source cannot ") + (clip ? "clip" : "bound") + " an object");
    if (const PovObject* patch = patchIn(objects.back()))
      in.error(first, (patch == &objects.back() ? "a " + patch->keyword
                                                : "this " + objects.back().keyword + " holds a " +
                                                      patch->keyword + ", which") +
                          " has no inside: it cannot " + (clip ? "clip" : "bound") +
                          " an object (POV-Ray refuses patch objects in " + std::string(t.text()) +
                          ": triangles, bicubic patches, parametrics and meshes without "
                          "inside_vector)");
  }
  if (objects.empty())
    in.error(in.peek(),
             std::string(t.text()) + " needs at least one object, not " + in.peek().describe());
  PovTransform after;
  for (;;) {
    const Token n = in.next();
    if (n.is("}")) break;
    if (!readTransform(n, in, after))
      in.error(n, "an object or a transform expected in " + std::string(t.text()) + ", not " +
                      n.describe());
  }
  // A clip asks its objects' inside, as a CSG does: open height fields and lathes closed.
  if (clip) {
    std::vector<std::pair<SourceLoc, std::string>> closed;
    for (PovObject& c : objects) closeForCsg(c, closed);
    for (const auto& [loc, message] : closed) warn(in, loc, message);
  }
  for (PovObject& c : objects) {
    c.transform = c.transform.then(after).then(backToObject);
    o.nodes += c.nodes;
    mine.push_back(std::move(c));
  }
}

// translate, rotate, scale, matrix and transform: `m` then the one written.
bool SceneReader::readTransform(const Token& t, TokenStream& in, PovTransform& m) {
  if (t.kind != TokenKind::Keyword) return false;
  const std::string_view w = t.text();
  if (w == "translate") {
    m.translate(toVec3(in.parseVector()));
  } else if (w == "rotate") {
    m.rotate(toVec3(in.parseVector()));
  } else if (w == "scale") {
    Vec3 s = toVec3(in.parseVector());
    for (int i = 0; i < 3; ++i)
      if (s[i] == 0.0) {
        // POV-Ray's own rule: a zero factor is replaced by 1, with a warning.
        warn(in, t.loc(), "scale by 0 is taken as 1 (as POV-Ray does)");
        s[i] = 1.0;
      }
    m.scale(s);
  } else if (w == "matrix") {
    in.expect("<");
    std::array<double, 12> e{};
    for (int i = 0; i < 12; ++i) {
      if (i > 0) in.parseComma();
      e[static_cast<size_t>(i)] = in.parseFloat();
    }
    in.expect(">");
    m = m.then(PovTransform::matrix(e));
  } else if (w == "transform") {
    if (in.allow("{")) {
      m = m.then(readTransformBlock(in));
    } else {
      const Token id = in.next();
      const auto* item = use<TransformItem>(id, in);
      if (!item) in.error(id, "a transform identifier or '{' expected, not " + id.describe());
      m = m.then(item->transform);
    }
  } else {
    return false;
  }
  return true;
}

// The inside of `transform { ... }` (the '{' read): transforms and identifiers in order,
// and `inverse`, which inverts the whole.
PovTransform SceneReader::readTransformBlock(TokenStream& in) {
  PovTransform m;
  bool inverse = false;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (const auto* item = use<TransformItem>(t, in)) {
      m = m.then(item->transform);
    } else if (isWord(t, "inverse")) {
      inverse = !inverse;
    } else if (!readTransform(t, in, m)) {
      in.error(t, "unexpected " + t.describe() + " in a transform");
    }
  }
  return inverse ? m.inverse() : m;
}

}  // namespace lucent::sdl
