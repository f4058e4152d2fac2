// POV-Ray's object pattern, `object { OBJECT [transforms] LIST }` in a pigment, a normal or
// a texture: the object becomes a node of the scene's <defs> (so that `lucent convert`
// writes it and the pattern's object="id"), its solid built once. The pattern's point is
// in POV-Ray's space, so the node is a group that carries Lucent's shape back by the
// importer's z mirror (pov_space.h).
#include "scene_reader.h"

#include "scenegraph/flatten.h"
#include "scenegraph/located_error.h"
#include "scenegraph/shape_registry.h"

namespace lucent::sdl {

namespace {

// POV-Ray asks the object's inside alone: its textures are left out of the node.
void dropTextures(PovObject& o) {
  o.texture.reset();
  for (PovObject& c : o.children.edit()) dropTextures(c);
  for (PovObject& c : o.clip) dropTextures(c);
  for (PovObject& c : o.bound) dropTextures(c);
}

bool isTransformWord(const Token& t) {
  return isWord(t, "translate") || isWord(t, "rotate") || isWord(t, "scale") ||
         isWord(t, "matrix") || isWord(t, "transform");
}

}  // namespace

std::shared_ptr<const ObjectPattern> SceneReader::readObjectPatternObject(const Token& t,
                                                                          TokenStream& in) {
  in.expect("{");
  // One object, declared or written out (POV-Ray's Parse_Bound_Clip, then its check).
  std::vector<PovObject> objects;
  for (;;) {
    const Token& next = in.peek();
    if (const auto* item = dynamic_cast<const ObjectItem*>(itemOf(next))) {
      const Token name = in.next();
      use<ObjectItem>(name, in);
      objects.push_back(item->object);
    } else if (isObjectKeyword(next)) {
      const Token first = in.next();
      objects.push_back(readObject(first, in));
    } else {
      break;
    }
  }
  if (objects.size() != 1)
    in.error(objects.empty() ? in.peek() : t,
             "object or object identifier expected (an object pattern holds one object)");
  PovObject object = std::move(objects.front());
  if (object.kind == NodeKind::Light)
    in.error(object.loc, "a light source cannot be an object pattern's object");
  PovTransform after;
  while (isTransformWord(in.peek())) {
    const Token k = in.next();
    readTransform(k, in, after);
  }
  object.transform = object.transform.then(after);
  dropTextures(object);

  const PovTexture texture = defaultTexture();
  const PovInterior interior;
  Inherited top;
  top.texture = &texture;
  top.interior = &interior;
  std::unique_ptr<Node> node = toNode(object, top, true, in);
  auto group = std::make_unique<Node>();
  group->kind = NodeKind::Group;
  group->element = "group";
  group->loc = t.loc();
  group->id = "object-pattern-" + std::to_string(++objectPatterns_);
  // Pattern space is POV-Ray's: the node's Lucent shape is carried there by the mirror.
  group->parentFromNode = Mat4(1.0);
  group->parentFromNode[2][2] = -1.0;
  if (node) group->children.push_back(std::move(node));

  auto pattern = std::make_shared<ObjectPattern>();
  pattern->id = group->id;
  pattern->node = group.get();
  try {
    pattern->solid = buildSolid(scene_, *group, makeShape);
  } catch (const LocatedError& e) {
    in.error(e.loc(), e.message());
  }
  if (!pattern->solid) in.error(t, "the object pattern's object has no shape Lucent can build");
  scene_.defs.push_back(std::move(group));
  return pattern;
}

}  // namespace lucent::sdl

namespace lucent::sdl {

PatternTexture SceneReader::objectPatternTexture(std::shared_ptr<const ObjectPattern> object,
                                                 const Texture& was) {
  PatternTexture tex;
  Texture copy = was;
  if (const PatternPlacement* p = placementOf(copy)) tex.pattern.placement = *p;
  tex.pattern.type = PatternType::object;
  tex.pattern.frequency = defaultFrequency(PatternType::object);
  tex.pattern.noiseGenerator = 0;  // the scene's global_settings noise_generator
  tex.pattern.object = std::move(object);
  return tex;
}

void SceneReader::readObjectPigment(const Token& t, TokenStream& in, PovPigment& p) {
  p.pattern = objectPatternTexture(readObjectPatternObject(t, in), p.pattern);
  // POV-Ray's colours for those not written (its checker's default map).
  p.map = {{0, Color(0.0f, 0.0f, 1.0f)}, {1, Color(0.0f, 1.0f, 0.0f)}};
  p.mapLoc = t.loc();
  if (isWord(in.peek(), "pigment")) {
    readBlockPigments(in, p, 2);
  } else {
    for (size_t i = 0; i < 2 && isColourStart(in.peek()); ++i) {
      const PovColour c = readColour(in);
      p.map[i] = {double(i), c.rgb, c.filter, c.transmit};
      in.allow(",");
    }
  }
  in.expect("}");
}

// POV-Ray 3.7 fills a list shorter than two with the #default normal, as a block
// pattern's; Lucent needs the list (without one POV-Ray's normal is unclear).
void SceneReader::readObjectNormal(const Token& t, TokenStream& in, PovNormal& n) {
  PatternTexture tex = objectPatternTexture(readObjectPatternObject(t, in), Texture{});
  tex.pattern.placement = n.spec.pattern.placement;
  n.spec.pattern = tex.pattern;
  n.spec.block = NormalBlock::none;
  n.spec.map.clear();
  n.spec.slopeMap.clear();
  n.spec.average.clear();
  n.average = false;
  n.patterned = true;
  readNormalList(in, n, 2);
  in.expect("}");
  // POV-Ray's optional amount after the pattern (unused by a list of normals).
  if (in.allow(",") || startsNumber(in.peek())) n.spec.depth = in.parseFloat();
  if (n.spec.map.empty()) {
    keepError(in, t.loc(),
              "an object pattern in a normal without its list of normals is not supported by "
              "Lucent (give it normal {..} normal {..})");
    return;
  }
  while (n.spec.map.size() < 2) {
    if (!defaults_.normal || !defaults_.normal->patterned) {
      keepError(in, t.loc(),
                "the object pattern's list of normals needs 2 normals here (POV-Ray 3.7 fills "
                "a shorter list with the #default normal, and there is none)");
      return;
    }
    NormalMapEntry e;
    e.at = static_cast<double>(n.spec.map.size());
    e.normal = defaults_.normal->spec;
    e.normal.pattern.placement.patternFromObject =
        glm::inverse(defaults_.normal->transform.povMatrix());
    n.spec.map.push_back(std::move(e));
  }
}

}  // namespace lucent::sdl
