#include "scene_reader.h"

#include "read_support.h"

#include "scenegraph/light_placement.h"

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
      {"rainbow", "rainbows"},
      {"subsurface", "subsurface light transport"},
      {"caustics", "faked caustics"},
      {"dispersion", "dispersion"},
      {"interior_texture", "a texture for the inside of a surface"},
      {"clipped_by", "clipping; the nearest Lucent feature is <intersection>"},
      {"projected_through", "lights projected through objects"},
      {"no_image", "objects hidden from the camera"},
      {"no_reflection", "objects hidden from reflections"},
      {"double_illuminate", "surfaces lit from both sides"},
      {"material_map", "material maps"},
  };
  return features;
}

// Skips tokens to the brace that closes the block `depth` levels out.
void skipToClose(TokenStream& in, int depth) {
  while (depth > 0) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) in.error(t, "the block is not closed ('}' expected)");
    if (t.is("{")) ++depth;
    if (t.is("}")) --depth;
  }
}

}  // namespace

void SceneReader::keepError(TokenStream& in, const SourceLoc& at, const std::string& message) {
  // The core adds the macro and include chain that led here as notes.
  try {
    in.error(at, message);
  } catch (const SdlError& e) {
    diags_.error(e.loc(), e.message());
  }
}

void SceneReader::warn(TokenStream& in, const SourceLoc& at, const std::string& message) {
  if (warned_.insert(at.str() + message).second) in.warning(at, message);
}

void SceneReader::refusal(TokenStream& in, const SourceLoc& at, const std::string& message,
                          bool here) {
  if (options_.skipUnsupported) {
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
  if (t.kind != TokenKind::Keyword) in.error(t, "unexpected " + t.describe() + " in this block");
  unsupported(t, in, false);
  skipToClose(in, 1);
}

ItemPtr SceneReader::read(const Token& t, TokenStream& in) {
  const Token first = t;
  if (isObjectKeyword(first)) {
    auto item = std::make_shared<ObjectItem>();
    ++declaring_;
    try {
      item->object = readObject(first, in);
    } catch (...) {
      --declaring_;
      throw;
    }
    --declaring_;
    return item;
  }
  if (isWord(first, "camera")) {
    auto item = std::make_shared<CameraItem>();
    item->camera = readCamera(in);
    item->camera.loc = first.loc();
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
    return item;
  }
  if (isWord(first, "transform")) {
    auto item = std::make_shared<TransformItem>();
    in.expect("{");
    item->transform = readTransformBlock(in);
    return item;
  }
  return nullptr;
}

void SceneReader::readScene(TokenStream& in) {
  for (;;) {
    const Token t = in.next();
    if (t.kind == TokenKind::End) return;
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
    } else if (isWord(t, "sky_sphere")) {
      readSkySphere(t.loc(), in);
    } else if (isObjectKeyword(t)) {
      place(readObject(t, in), in);
    } else if (t.kind == TokenKind::Keyword) {
      unsupported(t, in, true);
    } else {
      in.error(t, "unexpected " + t.describe() + " at the top level of the scene");
    }
  }
}

// `#default { texture { } pigment { } finish { } }`: what later textures start from.
void SceneReader::readDefault(TokenStream& in) {
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return;
    if (isWord(t, "pigment")) {
      defaults_.pigment = readPigment(in, defaults_.pigment);
    } else if (isWord(t, "finish")) {
      defaults_.finish = readFinish(in, defaults_.finish);
    } else if (isWord(t, "texture")) {
      const PovTexture tex = readTexture(in, defaultTexture());
      defaults_.pigment = tex.pigment;
      defaults_.finish = tex.finish;
    } else {
      unreadInBlock(t, in);
      return;
    }
  }
}

void SceneReader::place(const PovObject& object, TokenStream& in) {
  const PovTexture tex = defaultTexture();
  const PovInterior interior;
  std::unique_ptr<Node> node = toNode(object, &tex, &interior, true, in);
  if (!node) return;  // left out (--skip-unsupported)
  if (node->kind == NodeKind::Light) scene_.lightRoot->children.push_back(std::move(node));
  else scene_.root->children.push_back(std::move(node));
}

// An object's nodes. POV-Ray gives an object without a texture its parent's (a CSG's
// texture goes to the operands that have none), and a top-level one the default texture:
// `texture` and `interior` are what the object inherits.
std::unique_ptr<Node> SceneReader::toNode(const PovObject& o, const PovTexture* texture,
                                          const PovInterior* interior, bool topLevel,
                                          TokenStream& in) {
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
    return n;
  }
  for (const auto& [at, message] : o.refusals)  // a declared object's, now in the scene
    if (refused_.insert(at.str() + message).second) refusal(in, at, message, false);
  // Left out (--skip-unsupported): a shape Lucent has not.
  if (o.kind == NodeKind::Shape && !o.shape && options_.skipUnsupported) return nullptr;
  n->parentFromNode = o.transform.lucentMatrix();
  n->shape = o.shape;
  n->shadows = !o.noShadow;
  n->inverse = o.inverse;
  const bool own = o.texture || o.interior;
  if (o.texture) texture = &*o.texture;
  if (o.interior) interior = &*o.interior;
  // A top-level object and one with its own texture or interior get a material; an
  // operand without either inherits its parent's node material.
  if (own || topLevel) {
    MaterialImport imported = importMaterial(texture->pigment, texture->finish, *interior);
    const SourceLoc at = o.texture ? o.textureLoc : o.loc;
    for (const std::string& d : imported.differences) warn(in, at, d);
    imported.material.loc = at;
    scene_.materials.push_back(imported.material);
    n->material = static_cast<uint32_t>(scene_.materials.size() - 1);
  }
  for (const PovObject& c : o.children)
    if (auto child = toNode(c, texture, interior, false, in))
      n->children.push_back(std::move(child));
  return n;
}

void SceneReader::finishScene(TokenStream& in) {
  for (const auto& [key, s] : skipped_)
    in.warning(s.first, "left out (--skip-unsupported): " + s.message + "; " +
                            std::to_string(s.count) + (s.count == 1 ? " place" : " places") +
                            ", the first here");
  const int width = options_.imageWidth, height = options_.imageHeight;
  scene_.render.width = width;
  scene_.render.height = height;
  for (const std::string& d : applyGlobalSettings(global_, background_, scene_.render))
    warn(in, globalLoc_.line > 0 ? globalLoc_ : SourceLoc{scene_.file, 0, 0}, d);
  const PovCamera camera = camera_ ? *camera_ : PovCamera{};
  const SourceLoc cameraLoc = camera_ ? camera.loc : SourceLoc{scene_.file, 0, 0};
  CameraImport imported = importCamera(camera, width, height);
  if (!imported.error.empty()) {
    keepError(in, cameraLoc, imported.error);
    return;
  }
  for (const std::string& d : imported.differences) warn(in, cameraLoc, d);
  imported.camera.loc = cameraLoc;
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
