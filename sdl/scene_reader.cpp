#include "scene_reader.h"

#include "deep_stack.h"

#include "pov_bounds.h"

#include "read_support.h"

#include "scenegraph/light_placement.h"
#include "scenegraph/linear_placement.h"
#include "scenegraph/map_blend.h"

#include <fmt/format.h>

#include <cmath>

#include <functional>
#include <map>

namespace lucent::sdl {

namespace {

// POV-Ray's features Lucent has no equivalent of, with the nearest one Lucent has.
const std::map<std::string_view, std::string_view>& unsupportedFeatures() {
  static const std::map<std::string_view, std::string_view> features = {
      {"media", "participating media; the nearest Lucent feature is <fog>"},
      {"radiosity", "global illumination; ambient_light stands in for it"},
      {"photons", "photon mapping of caustics"},
      {"subsurface", "subsurface light transport"},
      {"caustics", "faked caustics"},
      {"dispersion", "dispersion"},
      {"texture_map", "maps of textures; Lucent has one texture layer per material"},
      {"uv_mapping",
       "uv_mapping here; Lucent reads a uv-mapped pigment, normal, texture or object at "
       "POV-Ray's (u,v)"},
  };
  return features;
}

// A light's looks_like or projected_through object moved on by the light's transforms after
// it (`light`: all of them).
PovObject placedWithLight(const PovLooksLike& held, const PovTransform& light) {
  PovObject o = held.object;
  o.transform = o.transform.then(held.lightAt.inverse()).then(light);
  return o;
}

}  // namespace

void SceneReader::keepError(TokenStream& in, const SourceLoc& at, const std::string& message) {
  // The core adds the macro and include chain that led here as notes.
  const SdlError e = in.errorAt(at, message);
  ++notesIssued_;
  // Inside a declaration the error waits for the item's use (reportRefused).
  if (!declaring_.empty()) declaring_.back().push_back({Severity::Error, e.loc(), e.message()});
  else diags_.error(e.loc(), e.message());
}

void SceneReader::reportRefused(const SceneItem& item, const SourceLoc& usedAt, TokenStream& in) {
  for (const Diagnostic& d : item.refused) {
    if (d.severity == Severity::Warning && declaring_.empty()) {
      warn(in, d.loc, d.message);
      continue;
    }
    if (!declaring_.empty()) {
      declaring_.back().push_back(d);  // reported when the declaration using it is used
      continue;
    }
    if (!refusalsReported_.insert(d.loc.str() + d.message).second) continue;
    if (options_.skipUnsupported) {
      refusal(in, d.loc, d.message, false);  // counted where the declaration is used
      continue;
    }
    // The use, with the macro and include chain that led to it, as notes.
    const std::string used = in.errorAt(usedAt, "").message();
    const std::string note = usedAt.str() + ": note: the declaration is used here";
    diags_.error(d.loc, d.message + "\n" + note + used);
  }
}

void SceneReader::refuseInBlock(const Token& t, TokenStream& in, const std::string& why) {
  keepError(in, t.loc(),
            "'" + std::string(t.text()) + "' is not supported by Lucent (" + why + ")");
  skipToClose(in, 1);
}

void SceneReader::warn(TokenStream& in, const SourceLoc& at, const std::string& message) {
  ++notesIssued_;
  // Inside a declaration the warning waits for the item's use, as errors do.
  if (!declaring_.empty()) declaring_.back().push_back({Severity::Warning, at, message});
  else if (warned_.insert(at.str() + message).second) in.warning(at, message);
}

void SceneReader::refusal(TokenStream& in, const SourceLoc& at, const std::string& message,
                          bool here) {
  ++notesIssued_;
  if (options_.skipUnsupported && declaring_.empty()) {
    // Counted by the feature's name, the first quoted word of the message.
    const size_t open = message.find('\'');
    const size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
    const std::string key =
        close == std::string::npos ? message : message.substr(open, close - open + 1);
    Skipped& s = skipped_[key];
    if (s.count++ == 0) {
      s.first = at;
      s.message = message;
    }
  } else if (here) {
    keepError(in, at, message);
  } else {
    diags_.error(at, message);
  }
}

void SceneReader::unsupported(const Token& t, TokenStream& in, bool skipBlock, PovObject* object) {
  const std::string word(t.text());
  const SourceLoc at = t.loc();
  const auto& features = unsupportedFeatures();
  const auto it = features.find(word);
  const std::string message =
      it != features.end()
          ? "'" + word + "' is not supported by Lucent (" + std::string(it->second) + ")"
          : "'" + word + "' is not read yet by Lucent's POV-Ray reader";
  if (object) refuse(*object, at, in, message);
  else refusal(in, at, message, true);
  if (skipBlock && in.peek().is("{")) {
    in.next();
    skipToClose(in, 1);
  }
}

void SceneReader::unreadInBlock(const Token& t, TokenStream& in) {
  // A declared item whose declaration was refused: the refusal, where it is used.
  if (const auto* item = dynamic_cast<const SceneItem*>(itemOf(t));
      item && !item->refused.empty()) {
    reportRefused(*item, t.loc(), in);
    skipToClose(in, 1);
    return;
  }
  if (t.kind != TokenKind::Keyword) in.error(t, "unexpected " + t.describe() + " in this block");
  unsupported(t, in, false);
  skipToClose(in, 1);
}

ItemPtr SceneReader::read(const Token& t, TokenStream& in) {
  // The errors of what Lucent cannot render, kept by the item instead of reported.
  struct Declaring {
    std::vector<std::vector<Diagnostic>>& stack;
    explicit Declaring(std::vector<std::vector<Diagnostic>>& s) : stack(s) { stack.emplace_back(); }
    ~Declaring() { stack.pop_back(); }
  } declaring(declaring_);
  std::shared_ptr<SceneItem> item = readItem(t, in);
  if (item) item->refused = std::move(declaring_.back());
  return item;
}

std::shared_ptr<SceneItem> SceneReader::readItem(const Token& t, TokenStream& in) {
  const Token first = t;
  const auto& features = unsupportedFeatures();
  if (first.kind == TokenKind::Keyword && features.count(first.text())) {
    auto item = std::make_shared<RefusedItem>();
    item->word = std::string(first.text());
    unsupported(first, in, true);
    return item;
  }
  if (isObjectKeyword(first)) {
    auto item = std::make_shared<ObjectItem>();
    item->object = readObject(first, in);
    return item;
  }
  if (isWord(first, "camera")) {
    auto item = std::make_shared<CameraItem>();
    item->camera = readCamera(in);
    item->camera.loc = first.loc();
    return item;
  }
  if (isWord(first, "sky_sphere")) {
    auto item = std::make_shared<SkySphereItem>();
    item->sky = readSkySphereBlock(first.loc(), in);
    return item;
  }
  if (isWord(first, "pigment_map")) {
    auto item = std::make_shared<PigmentMapItem>();
    item->entries = readPigmentMap(in, first);
    return item;
  }
  if (isWord(first, "pigment")) {
    auto item = std::make_shared<PigmentItem>();
    item->pigment = readPigment(in, defaults_.pigment);
    return item;
  }
  if (isWord(first, "finish")) {
    auto item = std::make_shared<FinishItem>();
    item->finish = readFinish(in, defaults_.finish);
    return item;
  }
  if (isWord(first, "texture")) {
    auto item = std::make_shared<TextureItem>();
    item->texture = readTexture(in, defaultTexture());
    item->texture.declaration = ++declarations_;
    item->texture.moved = false;  // as declared, its transforms included
    // `#declare T = texture {...} texture {...}`: the layers come after the declaration
    // (looking ahead here would run the directives that follow), read by readScene.
    lastTexture_ = item;
    return item;
  }
  if (isWord(first, "normal")) {
    auto item = std::make_shared<NormalItem>();
    item->normal = readNormal(in, nullptr);
    return item;
  }
  if (isWord(first, "color_map") || isWord(first, "colour_map")) {
    auto item = std::make_shared<ColorMapItem>();
    item->loc = first.loc();
    item->map = readColorMap(in, item->loc);
    return item;
  }
  if (isWord(first, "interior")) {
    auto item = std::make_shared<InteriorItem>();
    item->interior = readInterior(in, PovInterior{});
    return item;
  }
  if (isWord(first, "material")) {
    auto item = std::make_shared<MaterialItem>();
    item->material = readMaterial(in);
    if (item->material.texture) {
      item->material.texture->declaration = ++declarations_;
      item->material.texture->moved = false;
    }
    return item;
  }
  if (isWord(first, "transform")) {
    auto item = std::make_shared<TransformItem>();
    in.expect("{");
    item->transform = readTransformBlock(in);
    return item;
  }
  // Any other block (`#declare Q = quadric {...}`, a shape the reader does not read yet):
  // refused, where the declaration is used.
  if (first.kind == TokenKind::Keyword && in.peek().is("{")) {
    auto item = std::make_shared<RefusedItem>();
    item->word = std::string(first.text());
    unsupported(first, in, true);
    return item;
  }
  return nullptr;
}

void SceneReader::readScene(TokenStream& in) {
  for (;;) {
    const Token t = in.next();
    if (t.kind == TokenKind::End) return;
    if (!isWord(t, "texture")) lastTexture_.reset();
    if (isWord(t, "texture") && lastTexture_) {
      // A layer of the texture just declared (`#declare T = texture { } texture { }`): its
      // refusals are the declaration's, reported where it is used.
      declaring_.emplace_back();
      PovTexture top = readTexture(in, defaultTexture());
      const uint64_t declaration = lastTexture_->texture.declaration;
      lastTexture_->texture =
          layerOver(std::move(lastTexture_->texture), std::move(top), t.loc(), in);
      lastTexture_->texture.declaration = declaration;  // still that declaration
      lastTexture_->texture.moved = false;
      for (Diagnostic& d : declaring_.back()) lastTexture_->refused.push_back(std::move(d));
      declaring_.pop_back();
      continue;
    }
    if (t.kind == TokenKind::Keyword && t.kw == Kw::k_default) {
      readDefault(in);
    } else if (isWord(t, "camera")) {
      camera_ = readCamera(in);
      camera_->loc = t.loc();
    } else if (isWord(t, "global_settings")) {
      globalLoc_ = t.loc();
      readGlobalSettings(in);
    } else if (isWord(t, "background")) {
      readBackground(in);
    } else if (isWord(t, "fog")) {
      readFog(t.loc(), in);
    } else if (isWord(t, "rainbow")) {
      readRainbow(t.loc(), in);
    } else if (isWord(t, "sky_sphere")) {
      readSkySphere(t.loc(), in);
    } else if (startsObject(t)) {
      place(readObjectOrCopy(t, in), in);
    } else if (t.kind == TokenKind::Keyword) {
      unsupported(t, in, true);
    } else {
      in.error(t, "unexpected " + t.describe() + " at the top level of the scene");
    }
  }
}

// `#default { texture { } pigment { } normal { } finish { } }`: what later textures start
// from.
void SceneReader::readDefault(TokenStream& in) {
  defaultMaterial_.reset();  // objects from here on take the new defaults
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return;
    if (isWord(t, "pigment")) {
      defaults_.pigment = readPigment(in, defaults_.pigment);
    } else if (isWord(t, "finish")) {
      defaults_.finish = readFinish(in, defaults_.finish);
    } else if (isWord(t, "normal")) {
      defaults_.normal = readNormal(in, nullptr);  // starts from the default normal
    } else if (isWord(t, "texture")) {
      const PovTexture tex = readTexture(in, defaultTexture());
      defaults_.pigment = tex.pigment;
      defaults_.normal = tex.normal;
      defaults_.finish = tex.finish;
    } else {
      unreadInBlock(t, in);
      return;
    }
  }
}

void SceneReader::place(const PovObject& object, TokenStream& in) {
  // The default texture is placed in the scene's space: its transforms are its own.
  const PovTexture tex = defaultTexture();
  const PovInterior interior;
  Inherited top;
  top.texture = &tex;
  top.interior = &interior;
  top.framed = true;
  std::unique_ptr<Node> node = toNode(object, top, true, in);
  if (!node) return;  // left out (--skip-unsupported)
  if (node->kind == NodeKind::Light) scene_.lightRoot->children.push_back(std::move(node));
  else scene_.root->children.push_back(std::move(node));
}

namespace {

// Some layer of the texture (or of its entries) has a normal read at (u, v, 0).
bool holdsUvNormal(const PovTexture& t) {
  if (t.normal && t.normal->uv) return true;
  for (const PovTexture& layer : t.below)
    if (holdsUvNormal(layer)) return true;
  for (const PovTextureMapEntry& e : t.mapEntries)
    if (holdsUvNormal(e.texture)) return true;
  return false;
}

// Lucent's object space is POV-Ray's with z negated (pov_space.h): S.
Mat4 negateZ() {
  Mat4 s(1.0);
  s[2][2] = -1.0;
  return s;
}

}  // namespace

// The material of `texture` on a node: a pattern's point is the node's object point (in
// Lucent's space) taken to POV-Ray's (S), to the space the texture was placed in
// (textureFromNode) and into pattern space (the inverse of the pattern's transforms).
uint32_t SceneReader::addMaterial(const PovTexture& texture, const PovInterior& interior,
                                  bool hollow, const Mat4& textureFromNode, const SourceLoc& at,
                                  TokenStream& in) {
  const Mat4 objectToTexture = textureFromNode * negateZ();
  // A declared texture used as it is: one material for every object that uses it with the
  // same interior and, if it is patterned, the same placement of its pattern. Unpatterned,
  // it is named after the texture (convert writes it once, by name).
  bool declared = !texture.name.empty() && texture.declaration != 0;
  const bool patterned = declared && texture.patterned();
  // A patterned one is shared only as declared (its patterns' own transforms unchanged:
  // they are not part of the key).
  if (patterned && texture.moved) declared = false;
  DeclaredUse use{};
  if (declared) {
    use = {texture.declaration,
           interior.ior,
           interior.fadeDistance,
           interior.fadePower,
           interior.fadeColor.r,
           interior.fadeColor.g,
           interior.fadeColor.b,
           hollow,
           {}};
    if (patterned)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) use.placement[c * 4 + r] = objectToTexture[c][r];
    if (const auto it = declaredMaterials_.find(use); it != declaredMaterials_.end())
      return it->second;
  }
  const uint64_t notesBefore = notesIssued_;
  Material m = importTexture(texture, interior, objectToTexture, at, in);
  m.loc = at;
  m.hollow = hollow;
  if (!declared || notesIssued_ != notesBefore)
    return sharedMaterials_.add(scene_.materials, std::move(m));
  const auto index = static_cast<uint32_t>(scene_.materials.size());
  if (!patterned) {
    // Named after the texture; another declaration or interior of it takes a suffix.
    const int same = namedMaterialCount_[texture.name]++;
    m.id = same == 0 ? texture.name : texture.name + "-" + std::to_string(same + 1);
  }
  declaredMaterials_[use] = index;
  scene_.materials.push_back(std::move(m));
  return index;
}

// A texture as a Lucent material: one layer, layers (the bottom one the material itself,
// the others its <layer>s, bottom first) or a map, whose entries lie in its pattern space.
Material SceneReader::importTexture(const PovTexture& texture, const PovInterior& interior,
                                    const Mat4& objectToTexture, const SourceLoc& at,
                                    TokenStream& in, bool uv) {
  if (texture.mapped()) {
    // The interior terms of the whole, from a plain texture's import.
    Material m = importMaterial(PovPigment{}, PovFinish{}, interior).material;
    m.mapPattern = texture.mapPattern.pattern;
    const int cells = std::holds_alternative<HexagonTexture>(m.mapPattern) ? 3 : 2;
    if (!blockValuesUnchanged(texture.mapPattern.blockValueSpec(), cells))
      keepError(in, at,
                "frequency, phase or a wave on a block pattern's list of textures is not "
                "supported by Lucent (POV-Ray blends the listed textures by the changed cell "
                "number)");
    // A uv-mapped map and its entries read the shape's (u, v, 0), placed from there.
    const bool mapUv = uv || texture.mapPattern.uv;
    const Mat4 patternFromObject =
        texture.mapPattern.uv
            ? glm::inverse(texture.mapPattern.uvTransform.povMatrix())
            : glm::inverse(texture.mapPattern.transform.povMatrix()) * objectToTexture;
    if (PatternPlacement* p = placementOf(m.mapPattern)) {
      p->patternFromObject = patternFromObject;
      p->uv = mapUv;
    }
    // The entries are shaded at the map's warped point carried back by its linear
    // placement (render/map_entries.h), so they are placed from the map's space by it.
    const PatternPlacement* place = placementOf(m.mapPattern);
    const Mat4 entriesFromObject = place ? linearPatternFromObject(*place) : patternFromObject;
    if (place && mapUv && (place->turbulence != Vec3(0.0) || !place->warps.empty()))
      warn(in, at,
           "a uv-mapped texture_map's warps or turbulence: POV-Ray evaluates its entries at the "
           "warped (u, v) point, Lucent at (u, v) (the entries' patterns lie differently)");
    for (size_t k = 0; k < texture.mapEntries.size(); ++k) {
      const PovTextureMapEntry& e = texture.mapEntries[k];
      if (holdsUvNormal(e.texture))
        keepError(in, at,
                  "a uv-mapped normal in an entry of a texture map is not supported by Lucent "
                  "(POV-Ray bends it in the map's space)");
      if (k > 0 && e.at < texture.mapEntries[k - 1].at && !mapAverages(m))
        keepError(in, at, "a texture_map's entries out of ascending order are not supported");
      m.mapEntries.push_back(
          {e.at, importTexture(e.texture, interior, entriesFromObject, at, in, mapUv)});
    }
    m.fullTir = m.isTransmissive();
    return m;
  }
  std::vector<const PovTexture*> layers;
  for (const PovTexture& layer : texture.below) layers.push_back(&layer);
  layers.push_back(&texture);
  Material m = importLayer(*layers.front(), interior, objectToTexture, at, in, uv);
  for (size_t k = 1; k < layers.size(); ++k)
    m.layers.push_back(importLayer(*layers[k], interior, objectToTexture, at, in, uv));
  // Under total internal reflection POV-Ray continues the mirror ray with weight 1 where
  // the surface lets light through at all (every layer).
  if (m.layered()) m.fullTir = m.isTransmissive();
  return m;
}

void SceneReader::importCameraNormal(const PovCamera& camera, Camera& imported, TokenStream& in) {
  if (!camera.normal) return;
  const PovNormal& n = *camera.normal;
  if (n.bump) {
    keepError(in, camera.normalLoc,
              "a camera's bump_map is not supported by Lucent (a camera's normal is a pattern)");
    return;
  }
  if (!n.patterned) {
    keepError(in, camera.normalLoc, "a normal without a pattern (POV-Ray: 'No normal type given')");
    return;
  }
  if (n.uv) {
    keepError(in, n.uvLoc,
              "'uv_mapping' in a camera's normal is not supported by Lucent (a camera has no "
              "(u, v))");
    return;
  }
  Mat4 povFromLucent(1.0);
  povFromLucent[2][2] = -1.0;
  imported.normal = n.spec;
  imported.normal->pattern.placement.patternFromObject =
      glm::inverse(n.transform.povMatrix()) * povFromLucent;
}

// One layer of a texture as a Lucent material: its pigment, finish and normal, placed.
Material SceneReader::importLayer(const PovTexture& layer, const PovInterior& interior,
                                  const Mat4& objectToTexture, const SourceLoc& at, TokenStream& in,
                                  bool uv) {
  // POV-Ray 3.7 keeps 3.6's opacity of the local terms for scenes of an older #version.
  MaterialImport imported =
      importMaterial(layer.pigment, layer.finish, interior, in.effectiveLanguageVersion() < 3.7);
  for (const std::string& d : imported.differences) warn(in, at, d);
  Material& m = imported.material;
  if (PatternPlacement* p = placementOf(m.texture)) {
    // A uv-mapped pigment's pattern space is reached from (u, v, 0) by its own transforms.
    p->uv = uv || layer.pigment.uv;
    p->patternFromObject =
        layer.pigment.uv ? glm::inverse(layer.pigment.uvTransform.povMatrix())
                         : glm::inverse(layer.pigment.transform.povMatrix()) * objectToTexture;
  }
  if (uv && layer.normal)
    keepError(in, at,
              "a normal in an entry of a uv-mapped texture map is not supported by Lucent "
              "(POV-Ray bends it in the map's space at (u, v))");
  if (layer.normal && layer.normal->bump && layer.normal->uv)
    keepError(in, at,
              "a uv-mapped bump_map is not supported by Lucent (it reads a uv-mapped pattern "
              "normal; give the bump_map a planar projection of its own)");
  if (layer.normal && layer.normal->bump) {
    // A bump map is the normal's only perturbation (POV-Ray's bump_map pattern).
    m.bumpMap = layer.normal->bump;
    m.bumpMap->keepFacingAway = true;  // POV-Ray keeps a bent normal that faces away
    m.bumpMap->placement.patternFromObject =
        glm::inverse(layer.normal->transform.povMatrix()) * objectToTexture;
    m.bumpMap->placement.warps = layer.normal->spec.pattern.placement.warps;
  } else if (layer.normal && !layer.normal->patterned) {
    keepError(in, at, "a normal without a pattern (POV-Ray: 'No normal type given')");
  } else if (layer.normal) {
    m.normal = layer.normal->spec;
    m.normal->keepFacingAway = true;  // POV-Ray keeps a bent normal that faces away
    if (layer.normal->uv) placeUvNormal(*layer.normal, objectToTexture, *m.normal, at, in);
    else
      m.normal->pattern.placement.patternFromObject =
          glm::inverse(layer.normal->transform.povMatrix()) * objectToTexture;
  }
  return std::move(m);
}

// A normal read at (u, v, 0), placed by its block's own transforms T and bent where POV-Ray
// bends it: the world normal (a normal's own uv_mapping, an object's), or the normal of the
// space the texture was placed in (a texture's uv_mapping: the object's transforms after
// the texture). Lucent's world and object spaces are POV-Ray's with z negated; a placement
// T⁻¹·S (the mirror first, which leaves (u, v, 0) as it is) carries Lucent's normal into
// POV-Ray's pattern space exactly. Where transforms before the texture turn or stretch the
// shape, Lucent's object space is not the texture's: refused.
void SceneReader::placeUvNormal(const PovNormal& normal, const Mat4& objectToTexture,
                                NormalSpec& spec, const SourceLoc& at, TokenStream& in) {
  Mat4 mirror = negateZ();
  if (!normal.bendInWorld) {
    // The texture's space (the transforms after it) from Lucent's object space, up to a
    // uniform scale: S or I. The normal's transforms beyond its block's own are those that
    // carried it back over the object's transforms before the texture.
    const Mat3 x(normal.uvTransform.povMatrix() * glm::inverse(normal.transform.povMatrix()) *
                 objectToTexture);
    const double scale = std::cbrt(std::abs(glm::determinant(x)));
    auto matches = [&](const Mat3& m) {
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
          if (std::abs(x[c][r] / scale - m[c][r]) > 1e-9) return false;
      return true;
    };
    if (scale > 0.0 && matches(Mat3(1.0))) mirror = Mat4(1.0);
    else if (!(scale > 0.0 && matches(Mat3(negateZ()))))
      keepError(in, at,
                "a normal in a uv-mapped texture on a shape turned or stretched before the "
                "texture is not supported by Lucent (POV-Ray bends it in the texture's space, "
                "Lucent in the shape's)");
  }
  spec.pattern.placement.uv = true;
  spec.pattern.placement.patternFromObject = glm::inverse(normal.uvTransform.povMatrix()) * mirror;
  spec.bendInWorld = normal.bendInWorld;
}

// An object's nodes. POV-Ray gives an object without a texture its parent's (a CSG's
// texture goes to the operands that have none), and a top-level one the default texture.
// A patterned texture is placed where it was written: every shape under it whose object
// space lies differently in the texture's space gets a material of its own.
std::unique_ptr<Node> SceneReader::toNode(const PovObject& o, const Inherited& inherited,
                                          bool topLevel, TokenStream& in) {
  auto n = std::make_unique<Node>();
  n->kind = o.kind;
  n->element = o.keyword;
  n->loc = o.loc;
  if (o.light) {
    PovLight light = *o.light;
    light.transform = light.transform.then(o.transform);
    LightImport imported = importLight(light);
    for (const std::string& d : imported.differences) warn(in, light.loc, d);
    imported.light.loc = light.loc;
    n->kind = NodeKind::Light;
    n->light = std::make_unique<Light>(imported.light);
    if (light.projectedThrough) {
      // projected_through: its object moved on by the light's transforms written after it,
      // in the light node's frame (the parent's: the light's transforms are in its place).
      const PovObject object = placedWithLight(*light.projectedThrough, light.transform);
      auto group = std::make_shared<Node>();
      group->kind = NodeKind::Group;
      group->element = "projected_through";
      group->loc = object.loc;
      if (auto child = toNode(object, inherited, false, in))
        group->children.push_back(std::move(child));
      if (!group->children.empty()) n->light->projectedThrough = std::move(group);
    }
    if (!light.looksLike) return n;
    // looks_like: the light and its object in a union, the object moved on by the light's
    // transforms written after looks_like.
    const PovObject shape = placedWithLight(*light.looksLike, light.transform);
    auto both = std::make_unique<Node>();
    both->kind = NodeKind::Union;
    both->element = "light_source";
    both->loc = o.loc;
    both->children.push_back(std::move(n));
    if (auto object = toNode(shape, inherited, topLevel, in))
      both->children.push_back(std::move(object));
    return both;
  }
  // Left out (--skip-unsupported): a shape Lucent has not.
  if (o.kind == NodeKind::Shape && !o.shape && options_.skipUnsupported) return nullptr;
  n->parentFromNode = o.transform.lucentMatrix();
  if (o.shape) n->shape = *o.shape;
  n->shadows = !o.noShadow;
  n->image = !o.noImage;
  n->reflection = !o.noReflection;
  n->doubleIlluminate = o.doubleIlluminate;
  n->inverse = o.inverse;
  n->lightGroup = o.lightGroup;
  n->globalLights = o.globalLights;
  if (o.lightGroup) n->element = "light_group";
  Inherited here = inherited;
  here.hollow = o.hollow.value_or(inherited.hollow);
  // A hollow flag that differs from the parent's material's needs a material of its own.
  const bool own = o.texture || o.interior || here.hollow != inherited.hollow;
  if (o.texture) here.texture = &*o.texture;
  if (o.interior) here.interior = &*o.interior;
  // The texture's space: this object's own (before its transforms) when it wrote the
  // texture (whose transforms lead there, PovObject::texture), else the parent's, which
  // this object's transforms lead to.
  const Mat4 textureFromNode =
      o.texture ? Mat4(1.0) : inherited.textureFromParent * o.transform.povMatrix();
  const bool placed = here.texture->patterned();
  const bool moved = placed && o.shape && textureFromNode != inherited.materialTextureFromNode;
  // A top-level object and one with its own texture or interior get a material, and a
  // shape under a pattern placed differently from its parent's material; the others
  // inherit their parent's node material.
  if (topLevel && !own && !placed && defaultMaterial_) {
    // An object of the default texture, unpatterned: the material made for the first such
    // object while this #default holds (a loop of a million spheres makes one, not a million).
    n->material = *defaultMaterial_;
    here.material = n->material;
    here.materialTextureFromNode = textureFromNode;
  } else if (own || topLevel || moved || !inherited.material) {
    const SourceLoc at = o.texture ? o.textureLoc : o.loc;
    n->material = addMaterial(*here.texture, *here.interior, here.hollow, textureFromNode, at, in);
    if (topLevel && !own && !placed) defaultMaterial_ = n->material;
    here.material = n->material;
    here.materialTextureFromNode = textureFromNode;
  }
  addInteriorMaterial(o, here, textureFromNode, *n, in);
  addComponentMaterials(o, here, *n, in);
  here.textureFromParent = textureFromNode;
  here.framed = inherited.framed && (o.kind == NodeKind::Union || o.lightGroup) && o.clip.empty() &&
                o.bound.empty();
  here.movedAfter = inherited.movedAfter || !o.transform.isIdentity();
  for (const PovObject& c : *o.children) {
    auto child = toNode(c, here, false, in);
    if (!child) continue;
    // A light group's light with looks_like stays its own light: out of the union with its
    // object, which stays in the group beside it.
    if (o.lightGroup && c.light && child->kind == NodeKind::Union) {
      n->children.push_back(std::move(child->children.front()));
      child->children.erase(child->children.begin());
    }
    n->children.push_back(std::move(child));
  }
  for (const PovObject& c : o.clip) {
    auto child = toNode(c, here, false, in);
    if (!child) continue;
    // A clip object inside nowhere (a triangle, say) leaves nothing of the object.
    if (!openOperands_.clipByInside(child)) return nullptr;
    n->clip.push_back(std::move(child));
  }
  if (keepsBound(o, inherited.framed)) {
    for (const PovObject& c : o.bound)
      if (auto child = toNode(c, here, false, in)) n->bound.push_back(std::move(child));
  } else if (inherited.framed && !inherited.movedAfter && !o.bound.empty() && !o.boundIsClip) {
    addBoxCut(o, here, *n, in);
  }
  // A CSG of objects that are not solids, as POV-Ray keeps it (nothing, sometimes). Where
  // POV-Ray links it to the frame, rays that miss its box miss it (an intersection's box
  // is its operands' met, a difference's its first operand's), and a disc's half-space
  // lets the surfaces kept reach beyond that box: the box is kept as a bound.
  const NodeKind operation = n->kind;
  std::optional<AABB> povBox;
  if (!openOperands_.rewrite(*n, inherited.framed, povBox)) return nullptr;
  if (povBox && inherited.framed &&
      (operation == NodeKind::Intersection || operation == NodeKind::Difference))
    addBoundBox(*povBox, o.loc, *n);
  return n;
}

// A blob's component textures: a material of each, in the blob's own space (its texture
// space: the component's transforms are in the texture's), with the blob's interior.
void SceneReader::addComponentMaterials(const PovObject& o, const Inherited& here, Node& n,
                                        TokenStream& in) {
  auto* blob = n.shape ? std::get_if<BlobSpec>(&*n.shape) : nullptr;
  if (!blob || o.componentTextures.empty()) return;
  blob->componentMaterials.clear();
  for (size_t k = 0; k < o.componentTextures.size(); ++k) {
    const auto& texture = o.componentTextures[k];
    blob->componentMaterials.push_back(
        texture ? std::optional<uint32_t>(addMaterial(*texture, *here.interior, here.hollow,
                                                      Mat4(1.0), o.componentTextureLocs[k], in))
                : std::nullopt);
  }
}

// interior_texture: a material of the texture (with the object's interior) for the node
// that wrote it, and for a shape below whose texture space lies otherwise (a patterned one);
// the others inherit their parent's. POV-Ray refuses one on an object without a texture.
void SceneReader::addInteriorMaterial(const PovObject& o, Inherited& here,
                                      const Mat4& textureFromNode, Node& n, TokenStream& in) {
  if (o.interiorTexture) {
    if (!o.texture)
      keepError(in, o.interiorTextureLoc,
                "'interior_texture' needs a texture of the object's own, as in POV-Ray");
    here.interiorTexture = &*o.interiorTexture;
  }
  if (!here.interiorTexture) return;
  const bool moved = here.interiorTexture->patterned() && o.shape &&
                     textureFromNode != here.interiorTextureFromNode;
  if (!o.interiorTexture && !moved && here.interiorMaterial) return;
  const SourceLoc at = o.interiorTexture ? o.interiorTextureLoc : o.loc;
  n.interiorMaterial =
      addMaterial(*here.interiorTexture, *here.interior, here.hollow, textureFromNode, at, in);
  here.interiorMaterial = n.interiorMaterial;
  here.interiorTextureFromNode = textureFromNode;
}

// An object linked to the frame whose bounds POV-Ray drops keeps their box as its own when
// that is smaller than its own box (by volume), unless an enclosing object moves it later
// (POV-Ray then computes its box from its shape again): rays that miss the box miss the
// object. Only a box that does not hold the object's changes the image, and only such a
// one is kept, as a <bound> box in the node's frame.
void SceneReader::addBoxCut(const PovObject& o, const Inherited& here, Node& n, TokenStream& in) {
  AABB cut = AABB::everything();
  for (const PovObject& c : o.bound) {
    if (c.inverse) continue;  // POV-Ray leaves an inverse bound out of the box
    if (auto b = toNode(c, here, false, in))
      cut = AABB::meet(cut, nodeBox(*b, n.parentFromNode, openOperands_.knownBoxes()));
  }
  if (!(boxVolume(cut) < boxVolume(nodeBox(n, Mat4(1.0), openOperands_.knownBoxes())))) return;
  addBoundBox(cut, o.bound.front().loc, n);
}

// `cut` (in n's parent's frame) as a <bound> box of n when it cuts into n's own box.
void SceneReader::addBoundBox(const AABB& cut, const SourceLoc& at, Node& n) {
  const AABB own = nodeBox(n, Mat4(1.0));
  if (!cut.isBounded() || cut.empty()) return;
  if (!own.empty() && glm::all(glm::lessThanEqual(cut.lo, own.lo)) &&
      glm::all(glm::greaterThanEqual(cut.hi, own.hi)))
    return;
  auto box = std::make_unique<Node>();
  box->kind = NodeKind::Shape;
  box->element = "box";
  box->loc = at;
  box->shape = BoxSpec{cut.lo, cut.hi};
  box->parentFromNode = glm::inverse(n.parentFromNode);
  n.bound.push_back(std::move(box));
}

// Whether POV-Ray tests the rays against an object's bounded_by (Ray_In_Bound): always in
// CSG that it keeps whole; for an object it links to the frame (Inherited::framed) it
// drops the bounds of the shapes cheap to intersect, keeping those of CSG, poly (cubic,
// quartic), text and a quadric (unless a clip gave the quadric its own box). Bounds linked
// with the clip (clipped_by { bounded_by } and the reverse) change nothing the clip does
// not: every point the clip keeps lies in them.
bool SceneReader::keepsBound(const PovObject& o, bool framed) {
  if (o.bound.empty() || o.boundIsClip) return false;
  if (!framed || o.kind != NodeKind::Shape) return true;
  if (!o.shape) return false;
  if (std::holds_alternative<PolySpec>(*o.shape) || std::holds_alternative<TextSpec>(*o.shape))
    return true;
  return o.keyword == "quadric" && o.clip.empty();
}

namespace {

void forEachPattern(Texture& t, const std::function<void(PatternSpec&)>& f);

// The pattern `s` and those of its pigment (pigment_pattern's, shared: changed on a copy).
void withPigmentPatterns(PatternSpec& s, const std::function<void(PatternSpec&)>& f) {
  f(s);
  if (!s.pigment) return;
  auto copy = std::make_shared<TextureMapEntry>(*s.pigment);
  forEachPattern(copy->texture, f);
  s.pigment = std::move(copy);
}

// Every pattern of a texture, those of the pigments in its maps and lists too.
void forEachPattern(Texture& t, const std::function<void(PatternSpec&)>& f) {
  std::vector<TextureMapEntry>* entries = nullptr;
  if (auto* p = std::get_if<PatternTexture>(&t)) {
    withPigmentPatterns(p->pattern, f);
    entries = &p->pigments;
  } else if (auto* c = std::get_if<CheckerTexture>(&t)) {
    entries = &c->pigments;
  } else if (auto* h = std::get_if<HexagonTexture>(&t)) {
    entries = &h->pigments;
  } else if (auto* b = std::get_if<BrickTexture>(&t)) {
    entries = &b->pigments;
  } else if (auto* a = std::get_if<AverageTexture>(&t)) {
    entries = &a->entries;
  }
  if (entries)
    for (TextureMapEntry& e : *entries) forEachPattern(e.texture, f);
}

// Every pattern of a normal, those of an average's normals too.
void forEachNormalPattern(NormalSpec& n, const std::function<void(PatternSpec&)>& f) {
  withPigmentPatterns(n.pattern, f);
  for (WeightedNormal& e : n.average) forEachNormalPattern(e.normal, f);
  for (NormalMapEntry& e : n.map) forEachNormalPattern(e.normal, f);
}

}  // namespace

void forEachTexturePattern(Texture& t, const std::function<void(PatternSpec&)>& f) {
  forEachPattern(t, f);
}

namespace {

// POV-Ray's inverse of a surface (a disc, a triangle) changes only its inside, which the CSG
// and clips around it have taken (sdl/open_operands.h): the surface itself is drawn the same.
// Lucent's inverse is for solids, so it is taken off surfaces once the scene is read.
void dropSurfaceInverse(Node& n) {
  if (n.kind == NodeKind::Shape && n.inverse && !n.isSolid()) n.inverse = false;
  for (auto& c : n.children) dropSurfaceInverse(*c);
  for (auto& c : n.clip) dropSurfaceInverse(*c);
  for (auto& c : n.bound) dropSurfaceInverse(*c);
}

}  // namespace

void SceneReader::finishScene(TokenStream& in) {
  if (scene_.root) dropSurfaceInverse(*scene_.root);
  for (const auto& [key, s] : skipped_)
    in.warning(s.first, "left out (--skip-unsupported): " + s.message + "; " +
                            std::to_string(s.count) + (s.count == 1 ? " place" : " places") +
                            ", the first here");
  // The patterns that did not choose a noise generator take global_settings' one, and
  // ripples and waves its number_of_waves (wherever global_settings stands in the file).
  auto noise = [&](PatternSpec& s) {
    if (s.noiseGenerator == 0) s.noiseGenerator = global_.noiseGenerator;
    if (s.type == PatternType::ripples || s.type == PatternType::waves)
      s.waveSources = global_.numberOfWaves;
  };
  std::function<void(Material&)> materialNoise = [&](Material& m) {
    forEachPattern(m.texture, noise);
    if (m.normal) forEachNormalPattern(*m.normal, noise);
    forEachPattern(m.mapPattern, noise);
    for (Material& layer : m.layers) materialNoise(layer);
    for (MaterialMapEntry& e : m.mapEntries) materialNoise(e.material);
  };
  for (Material& m : scene_.materials) materialNoise(m);
  // The pigments of pigment functions (their fields keep pointers to them: changed in place).
  for (const std::shared_ptr<PigmentFunction>& p : pigmentFunctions_)
    forEachPattern(p->pigment, noise);
  if (scene_.sky) {
    for (Texture& layer : scene_.sky->layers) forEachPattern(layer, noise);
    // POV-Ray layers a sky_sphere's pigments by the language version it renders with (the
    // last #version): below 3.7, by its older rule.
    if (in.effectiveLanguageVersion() < 3.7) scene_.sky->layering = SkyLayering::pov36;
  }
  // POV-Ray's fog turbulence always takes global_settings' noise generator.
  for (Fog& f : scene_.fogs)
    if (f.turbulence) f.turbulence->noiseGenerator = global_.noiseGenerator;
  const int width = options_.imageWidth, height = options_.imageHeight;
  scene_.render.width = width;
  scene_.render.height = height;
  for (const std::string& d :
       applyGlobalSettings(global_, background_, scene_.render, in.effectiveLanguageVersion()))
    warn(in, globalLoc_.line > 0 ? globalLoc_ : SourceLoc{scene_.file, 0, 0}, d);
  const PovCamera camera = camera_ ? *camera_ : PovCamera{};
  const SourceLoc cameraLoc = camera_ ? camera.loc : SourceLoc{scene_.file, 0, 0};
  CameraImport imported = importCamera(camera, width, height);
  if (!imported.error.empty()) {
    keepError(in, cameraLoc, imported.error);
    return;
  }
  importFocalBlur(camera, imported.camera, imported.differences);
  for (const std::string& d : imported.differences) warn(in, cameraLoc, d);
  imported.camera.loc = cameraLoc;
  if (camera.type == PovCameraType::Mesh && camera.normal)
    warn(in, camera.normalLoc,
         "the camera's normal on a mesh camera: left out (Lucent's mesh camera takes none)");
  else importCameraNormal(camera, imported.camera, in);
  if (imported.camera.normal) forEachNormalPattern(*imported.camera.normal, noise);
  scene_.cameras = {imported.camera};
  try {
    scene_.lights = placeLights(scene_, 10'000'000);
  } catch (const LocatedError& e) {
    diags_.error(e.loc(), e.message());
  }
}

namespace {

SceneLoad load(const Options& options, const std::string& file,
               const std::function<void(TokenStream&)>& open) {
  SceneLoad result;
  auto scene = std::make_unique<Scene>();
  scene->file = file;
  SceneReader reader(*scene, result.diagnostics, options);
  // 256 MB of address space, touched only as deep as the scene nests (sdl/deep_stack.h).
  runWithStack(std::size_t{256} << 20, [&] {
    try {
      TokenStream in(options, &reader);
      open(in);
      reader.readScene(in);
      if (!result.diagnostics.hasErrors()) reader.finishScene(in);
    } catch (const LocatedError& e) {
      result.diagnostics.error(e.loc(), e.message());
    } catch (const std::exception& e) {
      // Nothing a scene contains should get here; if it does, fail cleanly, not crash.
      result.diagnostics.error(SourceLoc{file, 0, 0},
                               std::string("internal error while reading the scene: ") + e.what());
    }
  });
  if (!result.diagnostics.hasErrors()) result.scene = std::move(scene);
  return result;
}

}  // namespace

SceneLoad loadScene(const std::filesystem::path& path, const Options& options) {
  return load(options, path.string(), [&](TokenStream& in) { in.openFile(path); });
}

SceneLoad loadSceneText(const std::string& name, const std::string& text,
                        const std::filesystem::path& folder, const Options& options) {
  return load(options, name, [&](TokenStream& in) { in.openText(name, text, folder); });
}

}  // namespace lucent::sdl
