// The camera, light sources, global_settings and background.
#include "read_support.h"
#include "scene_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent::sdl {

namespace {

// `area_light <axis1>, <axis2>, n1, n2` and its modifiers, which POV-Ray accepts before or
// after it (they count only with one).
void readAreaLight(const Token& t, TokenStream& in, PovLight& l) {
  if (!l.area) {
    l.area = PovAreaLight{};
    l.area->size1 = l.area->size2 = 1;  // a point light until area_light gives a grid
  }
  PovAreaLight& a = *l.area;
  if (isWord(t, "area_light")) {
    a.axis1 = toVec3(in.parseVector());
    in.parseComma();
    a.axis2 = toVec3(in.parseVector());
    in.parseComma();
    a.size1 = static_cast<int>(in.parseFloat());
    in.parseComma();
    a.size2 = static_cast<int>(in.parseFloat());
    if (a.size1 < 1 || a.size2 < 1) in.error(t, "an area light needs at least 1 light a side");
  } else if (isWord(t, "adaptive")) {
    a.adaptive = static_cast<int>(in.parseFloat());
  } else if (isWord(t, "jitter")) {
    a.jitter = optionalBool(in);
  } else if (isWord(t, "circular")) {
    a.circular = optionalBool(in);
  } else {
    a.orient = optionalBool(in);
  }
}

}  // namespace

PovCamera SceneReader::readCamera(TokenStream& in) {
  PovCamera c;
  in.expect("{");
  if (const auto* item = use<CameraItem>(in.peek(), in)) {
    in.next();
    c = item->camera;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return c;
    if (readTransform(t, in, c.transform)) continue;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "perspective") c.type = PovCameraType::Perspective;
    else if (w == "orthographic") c.type = PovCameraType::Orthographic;
    else if (w == "fisheye") c.type = PovCameraType::Fisheye;
    else if (w == "ultra_wide_angle") c.type = PovCameraType::UltraWideAngle;
    else if (w == "omnimax") c.type = PovCameraType::Omnimax;
    else if (w == "panoramic") c.type = PovCameraType::Panoramic;
    else if (w == "spherical") c.type = PovCameraType::Spherical;
    else if (w == "mesh_camera") readMeshCamera(t, in, c);
    else if (w == "cylinder") {
      c.type = PovCameraType::Cylinder;
      const Token number = in.peek();
      const double type = in.parseFloat();
      // POV-Ray truncates the number and knows types 1 to 4.
      if (!(type >= 1.0 && type < 5.0))
        in.error(number,
                 fmt::format("invalid cylinder camera type {}: the types are 1 to 4", type));
      c.cylinderType = static_cast<int>(type);
    } else if (w == "location") {
      c.location = toVec3(in.parseVector());
    } else if (w == "direction") {
      c.direction = toVec3(in.parseVector());
    } else if (w == "right") {
      c.right = toVec3(in.parseVector());
      c.rightGiven = true;
    } else if (w == "up") {
      c.up = toVec3(in.parseVector());
      c.upGiven = true;
    } else if (w == "sky") {
      c.sky = toVec3(in.parseVector());
    } else if (w == "look_at") {
      c.lookAt = toVec3(in.parseVector());
    } else if (w == "angle") {
      c.angle = in.parseFloat();
      if (startsNumber(in.peek()) || in.peek().is(",")) {
        in.parseComma();
        c.verticalAngle = in.parseFloat();
      }
    } else if (w == "normal") {
      // Starts from the camera's normal so far, or as any normal from the default one.
      c.normal = readNormal(in, c.normal ? &*c.normal : nullptr);
      c.normalLoc = t.loc();
    } else if (w == "aperture") {
      c.blur.aperture = in.parseFloat();
      c.blur.loc = t.loc();
    } else if (w == "blur_samples") {
      // blur_samples MAX, or MIN, MAX (POV-Ray takes whole numbers by truncation).
      const Token number = in.peek();
      const int first = static_cast<int>(std::clamp(in.parseFloat(), -1.0, 1e9));
      if (first <= 0) in.error(number, "illegal number of focal blur samples (at least 1)");
      c.blur.samples = first;
      c.blur.minSamples = 0;
      if (startsNumber(in.peek()) || in.peek().is(",")) {
        in.parseComma();
        const Token second = in.peek();
        const int most = static_cast<int>(std::clamp(in.parseFloat(), -1.0, 1e9));
        if (most != 0) {
          if (first > most)
            in.error(second, "focal blur samples minimum must not be larger than maximum");
          c.blur.minSamples = first;
          c.blur.samples = most;
        }
      }
    } else if (w == "confidence" || w == "variance") {
      // Out of range: POV-Ray warns and keeps the value it had.
      const double v = in.parseFloat();
      const bool confidence = w == "confidence";
      if (confidence ? (v > 0.0 && v < 1.0) : (v >= 0.0 && v <= 1.0))
        (confidence ? c.blur.confidence : c.blur.variance) = v;
      else
        warn(in, t.loc(),
             fmt::format("illegal {} value {}: the value before it is kept (as POV-Ray)", w, v));
    } else if (w == "focal_point") {
      c.blur.focalPoint = toVec3(in.parseVector());
    } else if (w == "bokeh") {
      in.error(t, "'bokeh' (a focal blur's lens shape) is not supported by Lucent");
    } else {
      unreadInBlock(t, in);
      return c;
    }
  }
}

// mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh {...} ... [smooth] } (no commas, as
// POV-Ray reads it), with POV-Ray's checks. Each mesh's faces are its triangles as read, in order;
// its transforms place them (a texture on it plays no part).
void SceneReader::readMeshCamera(const Token& t, TokenStream& in, PovCamera& c) {
  c.type = PovCameraType::Mesh;
  PovCamera::MeshCamera m;
  in.expect("{");
  const Token raysAt = in.peek();
  const double rays = in.parseFloat();
  if (!(rays >= 1.0)) in.error(raysAt, "rays per pixel may not be 0");
  if (rays > Camera::kMaxMeshRays)
    in.error(raysAt, fmt::format("{} rays per pixel: Lucent's mesh camera takes at most {}", rays,
                                 Camera::kMaxMeshRays));
  m.raysPerPixel = static_cast<int>(rays);
  const Token distributionAt = in.peek();
  const double distribution = in.parseFloat();
  if (!(distribution >= 0.0 && distribution < 4.0))
    in.error(distributionAt, "unrecognized mesh camera distribution (0 to 3)");
  m.distribution = static_cast<int>(distribution);
  if (m.distribution >= 2 && m.raysPerPixel != 1)
    in.error(raysAt, "rays per pixel must be 1 for distribution 2 or 3 (as POV-Ray)");
  if (startsNumber(in.peek())) m.maxDistance = in.parseFloat();
  while (isWord(in.peek(), "mesh") || isWord(in.peek(), "mesh2")) {
    const Token meshAt = in.next();
    const PovObject mesh = readObject(meshAt, in);
    if (!mesh.faces) in.error(meshAt, "the mesh camera's " + mesh.keyword + " has no faces");
    m.meshes.push_back({meshAt.loc(), mesh.faces, mesh.transform.lucentMatrix()});
  }
  if (isWord(in.peek(), "smooth")) {
    const Token smooth = in.next();
    if (m.distribution != 3)
      in.error(smooth, "smooth can only be used with distribution 3 (as POV-Ray)");
    m.smooth = true;
  }
  if (m.meshes.empty())
    in.error(t, "a mesh or mesh2 expected in mesh_camera, not " + in.peek().describe());
  in.expect("}");
  if (m.distribution == 0 && static_cast<size_t>(m.raysPerPixel) > m.meshes.size())
    in.error(raysAt, "rays per pixel must not exceed the number of meshes for distribution 0");
  if (m.distribution == 3 && m.meshes.size() > 1)
    warn(in, m.meshes[1].loc,
         "additional meshes after the first are ignored for distribution 3 (as POV-Ray)");
  c.mesh = std::move(m);
}

PovLight SceneReader::readLight(const SourceLoc& loc, TokenStream& in) {
  // The `{ OBJECT` that opens looks_like or projected_through (`keyword`): an object or a
  // declared one, not a light.
  auto lightsObject = [&](std::string_view keyword) {
    in.expect("{");
    const Token o = in.next();
    if (isObjectKeyword(o)) return readObject(o, in);
    if (const auto* item = use<ObjectItem>(o, in); item && !item->object.light) return item->object;
    in.error(o, "an object expected in " + std::string(keyword) + ", not " + o.describe());
  };
  PovLight l;
  l.loc = loc;
  in.expect("{");
  if (const auto* item = use<ObjectItem>(in.peek(), in); item && item->object.light) {
    in.next();
    l = *item->object.light;
    l.transform = l.transform.then(item->object.transform);
    l.loc = loc;
  } else {
    l.location = toVec3(in.parseVector());
    in.parseComma();
    l.color = readColour(in).rgb;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) {
      // POV-Ray's parser: a circular light needs a grid (a point light has size 0).
      if (l.area && l.area->circular && (l.area->size1 <= 1 || l.area->size2 <= 1))
        in.error(t,
                 "a circular area light must have more than 1 light along each axis, as "
                 "POV-Ray requires");
      return l;
    }
    if (readTransform(t, in, l.transform)) continue;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "color" || w == "colour" || (t.kind == TokenKind::Keyword && isColourKey(t.kw))) {
      in.unget();
      l.color = readColour(in).rgb;
    } else if (w == "spotlight" || w == "cylinder") {
      // POV-Ray's light has one type, which spotlight, cylinder and shadowless each set:
      // the last one written wins, and spotlight and cylinder start from their defaults.
      l.kind = w == "spotlight" ? PovLightKind::Spotlight : PovLightKind::Cylinder;
      l.radius.reset();
      l.falloff.reset();
      l.tightness = 0.0;
      l.shadowless = false;
    } else if (w == "parallel") {
      l.parallel = true;
    } else if (w == "point_at") {
      l.pointAt = toVec3(in.parseVector());
    } else if (w == "radius") {
      l.radius = in.parseFloat();
    } else if (w == "falloff") {
      l.falloff = in.parseFloat();
    } else if (w == "tightness") {
      l.tightness = in.parseFloat();
    } else if (w == "area_light" || w == "adaptive" || w == "jitter" || w == "circular" ||
               w == "orient") {
      readAreaLight(t, in, l);
    } else if (w == "shadowless") {
      // POV-Ray's shadowless light (its fill light) has no cone: a spotlight or cylinder
      // written before it lights as a point light (or a parallel one: cylinder's parallel
      // stays).
      l.shadowless = true;
      l.kind = PovLightKind::Point;
    } else if (w == "fade_distance") {
      l.fadeDistance = in.parseFloat();
    } else if (w == "fade_power") {
      l.fadePower = in.parseFloat();
    } else if (w == "media_attenuation") {
      l.mediaAttenuation = optionalBool(in);  // fog dims the light along shadow rays
    } else if (w == "media_interaction") {
      optionalBool(in);  // only media would see it, and media are refused
    } else if (w == "looks_like") {
      // POV-Ray moves the object to the light's centre, then applies the modifiers
      // written after it, and draws it with no_shadow (its light shines through it).
      if (l.looksLike) in.error(t, "only one looks_like per light_source, as POV-Ray allows");
      PovObject object = lightsObject(w);
      object.transform =
          object.transform.then(PovTransform::translation(l.transform.point(l.location)));
      readObjectModifiers(object, in);
      object.noShadow = true;
      l.looksLike =
          std::make_shared<const PovLooksLike>(PovLooksLike{std::move(object), l.transform});
    } else if (w == "projected_through") {
      // The light reaches a point only through the object, which follows the light's
      // transforms written after it and is never drawn; POV-Ray drops its texture and
      // interior with a warning each.
      if (l.projectedThrough)
        in.error(t, "only one projected_through per light_source, as POV-Ray allows");
      PovObject object = lightsObject(w);
      readObjectModifiers(object, in);
      if (object.texture) {
        warn(in, t.loc(),
             "projected_through objects cannot have a texture; texture removed (as POV-Ray)");
        object.texture.reset();
      }
      if (object.interior) {
        warn(in, t.loc(),
             "projected_through objects cannot have an interior; interior removed (as POV-Ray)");
        object.interior.reset();
      }
      l.projectedThrough =
          std::make_shared<const PovLooksLike>(PovLooksLike{std::move(object), l.transform});
    } else {
      unreadInBlock(t, in);
      return l;
    }
  }
}

void SceneReader::readGlobalSettings(TokenStream& in) {
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "assumed_gamma") {
      // POV-Ray's: a number or srgb; the first one counts.
      const bool srgb = isWord(in.peek(), "srgb");
      const double gamma = srgb ? (in.next(), 1.0) : in.parseFloat();
      if (!(gamma > 0.0))
        in.error(t,
                 fmt::format("assumed_gamma {}: a gamma must be above 0 (as POV-Ray says)", gamma));
      if (global_.assumedGamma) {
        warn(in, t.loc(), "a second assumed_gamma is ignored, as POV-Ray ignores it");
        continue;
      }
      global_.assumedGamma = gamma;
      global_.assumedGammaSrgb = srgb;
      in.setAssumedGamma(srgb ? 0.0 : gamma);
    } else if (w == "max_trace_level") {
      global_.maxTraceLevel = static_cast<int>(in.parseFloat());
    } else if (w == "adc_bailout") {
      global_.adcBailout = in.parseFloat();
    } else if (w == "ambient_light") {
      global_.ambientLight = readColour(in).rgb;
    } else if (w == "noise_generator") {
      const double g = in.parseFloat();
      if (g < 1 || g > 3) in.error(t, "noise_generator must be 1, 2 or 3");
      global_.noiseGenerator = static_cast<int>(g);
    } else if (w == "number_of_waves") {
      // The sources of every ripples and waves (finishScene gives them the count). POV-Ray
      // truncates the number and makes one below 1 into 1, with a warning.
      const double n = std::trunc(in.parseFloat());
      if (n < 1) {
        warn(in, t.loc(), "number_of_waves below 1 is 1 (as POV-Ray makes it)");
        global_.numberOfWaves = 1;
      } else if (n > kMaxWaveSources) {
        in.error(t, "number_of_waves above " + std::to_string(kMaxWaveSources) +
                        " is not supported by Lucent");
      } else {
        global_.numberOfWaves = static_cast<int>(n);
      }
    } else if (w == "max_intersections" || w == "mm_per_unit") {
      in.parseFloat();  // no effect on Lucent's image
    } else if (w == "hf_gray_16") {
      optionalBool(in);
    } else if (w == "irid_wavelength") {
      readColour(in);
      warn(in, t.loc(), "irid_wavelength is not imported (Lucent's irid uses POV-Ray's default)");
    } else if (w == "charset") {
      in.next();  // ascii, utf8 or sys: the core reads strings as bytes either way
    } else if (t.kind == TokenKind::Keyword) {
      unsupported(t, in, true);
    } else {
      in.error(t, "unexpected " + t.describe() + " in global_settings");
    }
  }
}

void SceneReader::readBackground(TokenStream& in) {
  in.expect("{");
  background_.color = readColour(in).rgb;
  in.expect("}");
}

}  // namespace lucent::sdl
