#include "tracer.h"

#include "adaptive_area.h"
#include "finish.h"
#include "fog.h"
#include "map_entries.h"
#include "optics.h"
#include "patterns/pattern_surface.h"
#include "rainbow.h"
#include "sampling.h"
#include "scenegraph/map_blend.h"
#include "see_through.h"
#include "shading_normal.h"
#include "sky_color.h"
#include "spawn.h"

#include "primitives/blob.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lucent {

namespace {

// How far short of a projected-through light's objects the shadows end, in world units:
// POV-Ray's SMALL_TOLERANCE.
constexpr double kProjectionTolerance = 0.001;

bool anyPositive(const Color& c) { return maxComponent(c) > 0.0f; }

// crand's u in [0, 1): a hash of the point's coordinates and the light's index.
double grain(const Vec3& p, size_t light) {
  const auto bitsOf = [](double v) {
    uint64_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  return hashToUnit(bitsOf(p.x), bitsOf(p.y), bitsOf(p.z), light);
}

// fade-on-exit: what the stretch inside keeps dims the rays that carry light out of the
// solid at this hit (Tracer::Hit::passOut, 1 otherwise), as POV-Ray's interior fade.
void dimPassingOut(SecondaryRays& rays, const Color& passOut) {
  if (passOut == Color(1.0f)) return;
  rays.transmitted *= passOut;
  if (rays.totallyReflected) rays.mirror *= passOut;
}

// What light keeps over `distance` inside m: its absorption and its fade (render/optics.h).
Color interiorAttenuation(const Material& m, double distance, bool shadowRay) {
  Color keep = m.isAbsorbing() ? beerLambert(m.absorption, distance) : Color(1.0f);
  if (m.hasFade())
    keep *= interiorFade(m.fadeColor, m.fadeDistance, m.fadePower, distance, shadowRay);
  return keep;
}

// The surface a slope pattern reads: the shading normal on the side of `v` (the
// geometric one where the interpolated normal faces away), as POV-Ray's raw normal
// turned against the ray, and the world point.
PatternSurface patternSurfaceAt(const SurfaceInfo& s, const Vec3& v) {
  const bool front = glm::dot(v, s.ng) > 0.0;
  Vec3 n = front ? s.ns : -s.ns;
  if (glm::dot(n, v) <= 0.0) n = front ? s.ng : -s.ng;
  return {n, s.p};
}

double boxVolume(const AABB& b) {
  if (!b.isBounded()) return kInf;
  Vec3 e = b.extent();
  return e.x * e.y * e.z;
}

}  // namespace

Tracer::Tracer(const World& world, ImageMapCache* textures)
    : world_(world),
      settings_(world.scene().render),
      lights_(world.scene().lights),
      sky_(world.scene().sky),
      fogs_(world.scene().fogs),
      rainbows_(world.scene().rainbows),
      slots_(world.scene().materials),
      textures_(slots_.materials(), textures, world.scene().render.workingGamma) {
  for (uint32_t k = 0; k < slots_.size(); ++k)
    seeThrough_.push_back(slots_[k].kind == SurfaceSlots::Kind::plain &&
                          textureSeeThrough(slots_[k].material->texture));
  for (const Material& m : world.scene().materials) {
    anyTransmissive_ = anyTransmissive_ || m.isTransmissive();
    anyAbsorbing_ = anyAbsorbing_ || (m.attenuates() && m.isTransmissive());
    patternSurface_ = patternSurface_ || usesPatternSurface(m);
  }
  for (const Light& light : lights_) {
    std::vector<Vec3> targets;
    if (light.type != LightType::Area || (!light.jitter && !light.orient))
      for (int k = 0, n = shadowSampleCount(light); k < n; ++k)
        targets.push_back(lightSamplePoint(light, k, Vec2(0.5)));
    fixedTargets_.push_back(std::move(targets));
  }
}

MediaStack Tracer::mediaAt(const Vec3& p) const {
  std::vector<std::pair<double, const Material*>> containing;
  // The box first: a mesh camera asks for every ray, and most solids are far from most
  // starts.
  for (const WorldObject& object : world_.objects())
    if (object.medium && object.shape->bounds().contains(p) && object.shape->inside(p))
      containing.push_back({boxVolume(object.shape->bounds()), object.medium});
  std::stable_sort(containing.begin(), containing.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  MediaStack media;
  for (const auto& c : containing) media.push(c.second);
  return media;
}

Color Tracer::traceCamera(const Ray& ray, const MediaStack& media, PathSeed& seed,
                          TraceContext& context) const {
  ++context.stats.primary;
  return trace(ray, 1, Color(1.0f), media, seed, context);
}

// One loop iteration per surface along a straight line: a transmitted ray that does not
// bend (equal indices of refraction, or a surface without an inside) continues in the
// loop at its parent's depth instead of recursing, so a ray through a thousand clear
// triangles needs no deep stack. Reflected and bent rays recurse with depth + 1.
Color Tracer::trace(Ray ray, int depth, Color weight, MediaStack media, PathSeed& seed,
                    TraceContext& context) const {
  RayStats& stats = context.stats;
  Color sum(0.0f);
  Color throughput(1.0f);  // k_t and absorption of the straight continuations so far
  for (;;) {
    WorldHit hit;
    ++stats.queries;
    // One call whatever the scene (World::intersectSeen): a choice made here, before the
    // call, cost 5 % of a glass scene's time.
    const bool found = world_.intersectSeen(ray, hit, context.reflected);
    if (!found) return sum + throughput * escaped(ray, media);

    const WorldLeaf& hitLeaf = hit.leaf();
    const SurfaceInfo s = hit.surface(ray);
    const bool solid = hitLeaf.medium != nullptr;  // the leaf bounds a medium (its material)
    const bool front = glm::dot(ray.d, s.ng) < 0.0;
    const MediumCrossing crossing = mediumCrossing(hitLeaf, hit.hit.flip, front, media);
    Hit here{hitLeaf, s, -glm::normalize(ray.d), front, crossing.leaving, crossing.medium};
    const Material* leaving = here.leaving ? here.medium : nullptr;
    // fade-on-exit: the stretch's attenuation waits for the rays that leave at this hit.
    if (leaving && leaving->fadeOnExit && leaving->attenuates())
      here.passOut = interiorAttenuation(*leaving, hit.t() * glm::length(ray.d), false);
    travelled(ray, hit.t(), leaving, media, sum, throughput);

    PatternSurface surface;
    if (patternSurface_) surface = patternSurfaceAt(s, here.v);
    const PatternSurfaceScope surfaceScope(patternSurface_, surface);
    const Shaded shaded = hitLeaf.componentMaterials
                              ? shadeComponents(here, depth, weight, media, seed, context)
                              : shadeSlot(surfaceSlot(hitLeaf, ray, s), here, depth, weight, media,
                                          seed, context, true);
    sum += throughput * shaded.result;
    const SecondaryRays& rays = shaded.rays;
    if (!rays.straight) return sum;
    Color w = weight * glm::abs(rays.transmitted);
    if (maxComponent(w) < settings_.minWeight) return sum;
    ++stats.refracted;
    weight = w;
    throughput *= rays.transmitted;
    ray = spawnRay(s, ray.d, settings_.epsilon);
    if (solid) media = shaded.beyond;
  }
}

Tracer::Shaded Tracer::shadeSlot(uint32_t slot, const Hit& h, int depth, const Color& weight,
                                 const MediaStack& media, PathSeed& seed, TraceContext& context,
                                 bool mayContinue) const {
  const SurfaceSlots::Slot& at = slots_[slot];
  switch (at.kind) {
    case SurfaceSlots::Kind::layers:
      return shadeLayers(at, h, depth, weight, media, seed, context, mayContinue);
    case SurfaceSlots::Kind::map:
      return shadeMap(at, h, depth, weight, media, seed, context);
    case SurfaceSlots::Kind::plain:
      break;
  }
  return shadeOne(slot, h, depth, weight, media, seed, context, mayContinue);
}

// POV-Ray chooses the interior texture where the ray runs along the surface's own normal
// (the interpolated one of a smooth triangle), from inside.
uint32_t Tracer::surfaceSlot(const WorldLeaf& leaf, const Ray& ray, const SurfaceInfo& s) {
  if (!leaf.interior || !(glm::dot(ray.d, s.ns) > 0.0)) return leaf.materialIndex;
  return leaf.interiorIndex;
}

const WorldLeaf& Tracer::surfaceLeaf(const WorldLeaf& leaf, const Ray& ray, const WorldHit& hit,
                                     WorldLeaf& inner) const {
  if (!leaf.interior) return leaf;
  const uint32_t slot = surfaceSlot(leaf, ray, hit.surface(ray));
  if (slot == leaf.materialIndex) return leaf;
  inner = leafOfSlot(leaf, slot);
  inner.transmissive = inner.material->isTransmissive();
  return inner;
}

WorldLeaf Tracer::leafOfSlot(const WorldLeaf& leaf, uint32_t slot) const {
  WorldLeaf out = leaf;
  out.material = slots_[slot].material;
  out.materialIndex = slot;
  return out;
}

Tracer::Shaded Tracer::shadeOne(uint32_t slot, const Hit& h, int depth, const Color& weight,
                                const MediaStack& media, PathSeed& seed, TraceContext& context,
                                bool mayContinue) const {
  const SurfaceInfo& s = h.s;
  // A layer or an entry: the leaf as its surface (the hit's own material needs no copy).
  std::optional<WorldLeaf> slotLeaf;
  if (slot != h.leaf.materialIndex) slotLeaf.emplace(leafOfSlot(h.leaf, slot));
  const WorldLeaf& hitLeaf = slotLeaf ? *slotLeaf : h.leaf;
  // A see-through texture: the material as it is at this point (render/see_through.h);
  // every other material is shaded as it is, with no copy.
  std::optional<Material> seen;
  std::optional<WorldLeaf> seenLeaf;
  if (seeThrough_[slot]) {
    const Material& own = *hitLeaf.material;
    seen.emplace(materialThrough(own, textures_.evalPigment(slot, own, s, *hitLeaf.instance)));
    seenLeaf.emplace(hitLeaf);
    seenLeaf->material = &*seen;
  }
  const WorldLeaf& leaf = seenLeaf ? *seenLeaf : hitLeaf;
  const Material& m = *leaf.material;
  const bool solid = leaf.medium != nullptr;

  Vec3 unbent;
  const Vec3 n = shadingNormal(leaf, s, h.front, h.v, unbent);
  Shaded out;
  out.result = localLight(leaf, s, n, h.v, h.leaving, media, seed, context);
  // The media are known by the hit's own material (the solid's medium).
  Interface side = interfaceAt(*h.leaf.material, m.transmissive, h, media);
  out.rays = secondaryRays(m, ShadingPoint{s.p, n, h.v}, solid, side.n1, side.n2,
                           reflectionTint(leaf, s), side.fresnel);
  dimPassingOut(out.rays, h.passOut);
  if (out.rays.straight && !mayContinue) {
    out.rays.straight = false;  // traced below, as a bent ray is
    out.rays.refracted = -h.v;
  }
  // A bent normal may send the mirror ray below the surface: it is turned back (with
  // n = unbent this is the plain mirror direction).
  const Vec3 mirror = reflectAboveSurface(-h.v, n, unbent);
  out.result = withBranches(out.result, s, mirror, out.rays, depth, weight, media, side.beyond,
                            seed, context);
  out.beyond = std::move(side.beyond);
  return out;
}

// POV-Ray 3.7's layered texture (its Trace::ComputeLightedTexture, as facts): from the top
// layer down, each layer's emission, ambient, diffuse and highlights, scaled by its opacity
// as a see-through texture's are, are multiplied by what the layers above let through;
// each layer's mirror ray is added undimmed; what all the layers let through weighs the
// ray refracted by the top layer's normal. Under total internal reflection the top layer's
// mirror ray carries it, and the lower layers whose normal is the top one's add no other.
Tracer::Shaded Tracer::shadeLayers(const SurfaceSlots::Slot& layers, const Hit& h, int depth,
                                   const Color& weight, const MediaStack& media, PathSeed& seed,
                                   TraceContext& context, bool mayContinue) const {
  const SurfaceInfo& s = h.s;
  const bool solid = h.leaf.medium != nullptr;
  // The indices on both sides whether or not the surface transmits here: a lower layer's
  // Fresnel reflection needs them.
  Interface side = interfaceAt(*h.leaf.material, Color(1.0f), h, media);
  std::vector<LayerMirror>& lower = context.layerMirrors;
  const size_t firstLower = lower.size();

  Shaded out;
  Color through(1.0f);  // what the layers above let through
  std::optional<Material> top;
  Vec3 topN(0.0), topUnbent(0.0);
  Color topTint(1.0f);
  for (uint32_t k = 0; k < layers.count; ++k) {
    const uint32_t slot = layers.first + k;
    const Material& own = *slots_[slot].material;
    WorldLeaf leaf = leafOfSlot(h.leaf, slot);
    std::optional<Material> seen;
    if (seeThrough_[slot])
      seen.emplace(materialThrough(own, textures_.evalPigment(slot, own, s, *leaf.instance)));
    else if (k == 0) seen.emplace(own);  // the top layer is kept for its refraction below
    leaf.material = seen ? &*seen : &own;
    const Material& m = *leaf.material;

    Vec3 unbent;
    const Vec3 n = shadingNormal(leaf, s, h.front, h.v, unbent);
    out.result += through * localLight(leaf, s, n, h.v, h.leaving, media, seed, context);
    const Color tint = reflectionTint(leaf, s);
    if (k == 0) {
      topN = n;
      topUnbent = unbent;
      topTint = tint;
    } else {
      const Color w = mirrorWeight(m, ShadingPoint{s.p, n, h.v}, side.fresnelPair().n1,
                                   side.fresnelPair().n2, tint);
      if (maxComponent(w) > 0.0f)
        lower.push_back({reflectAboveSurface(-h.v, n, unbent), n, w, 1.0 / m.reflectExponent});
    }
    through *= m.transmissive;
    if (k == 0) top = std::move(seen);
    // Nothing shows through any more: the layers below cannot be seen.
    if (!(maxComponent(glm::abs(through)) > 0.0f)) break;
  }

  // The top layer's mirror ray and the ray through all the layers.
  top->transmissive = through;
  out.rays = secondaryRays(*top, ShadingPoint{s.p, topN, h.v}, solid, side.n1, side.n2, topTint,
                           side.fresnel);
  dimPassingOut(out.rays, h.passOut);
  if (!(maxComponent(through) > 0.0f)) side.beyond = media;  // nothing crosses
  if (out.rays.straight && !mayContinue) {
    out.rays.straight = false;  // traced below, as a bent ray is
    out.rays.refracted = -h.v;
  }
  out.result = withBranches(out.result, s, reflectAboveSurface(-h.v, topN, topUnbent), out.rays,
                            depth, weight, media, side.beyond, seed, context);
  for (size_t i = firstLower; i < lower.size(); ++i) {
    const LayerMirror l = lower[i];  // a copy: the traces below push onto the same stack
    if (out.rays.totallyReflected && l.normal == topN) continue;
    SecondaryRays mirrorOnly;
    mirrorOnly.mirror = l.weight;
    mirrorOnly.mirrorPower = l.power;
    out.result = withBranches(out.result, s, l.direction, mirrorOnly, depth, weight, media,
                              side.beyond, seed, context);
  }
  lower.resize(firstLower);
  out.beyond = std::move(side.beyond);
  return out;
}

Tracer::Shaded Tracer::shadeMap(const SurfaceSlots::Slot& map, const Hit& h, int depth,
                                const Color& weight, const MediaStack& media, PathSeed& seed,
                                TraceContext& context) const {
  const Material& m = *map.material;
  SurfaceInfo moved;
  const Hit at{
      h.leaf,   mapEntrySurface(m.mapPattern, h.s, moved), h.v, h.front, h.leaving, h.medium,
      h.passOut};
  if (mapAverages(m)) return shadeAverage(map, at, depth, weight, media, seed, context);
  const MapBlend b = mapChoice(m, h.s, *h.leaf.instance);
  Shaded out;
  out.beyond = media;
  const bool both = b.b != b.a && b.wb > 0.0f;
  auto shade = [&](uint32_t entry, float w) {
    return w *
           shadeSlot(map.first + entry, at, depth, weight * w, media, seed, context, false).result;
  };
  // POV-Ray shades the upper entry first, so a slope in the lower one reads the normal the
  // upper one bent (its PNormal): only a scene with a slope depends on the order.
  const Color upper = both && patternSurface_ ? shade(b.b, b.wb) : Color(0.0f);
  out.result = shade(b.a, b.wa);
  if (both) out.result += patternSurface_ ? upper : shade(b.b, b.wb);
  return out;
}

// POV-Ray's Trace::ComputeAverageTextureColours, as facts: each entry shaded in order with
// the ray's own weight, its colour times its weight summed in single precision, the sum
// divided by the weights' sum.
Tracer::Shaded Tracer::shadeAverage(const SurfaceSlots::Slot& map, const Hit& h, int depth,
                                    const Color& weight, const MediaStack& media, PathSeed& seed,
                                    TraceContext& context) const {
  const Material& m = *map.material;
  Shaded out;
  out.beyond = media;
  float total = 0.0f;
  for (uint32_t k = 0; k < map.count; ++k) {
    const auto w = static_cast<float>(m.mapEntries[k].at);
    out.result +=
        w * shadeSlot(map.first + k, h, depth, weight, media, seed, context, false).result;
    total += w;
  }
  out.result /= total;
  return out;
}

void Tracer::componentWeights(const WorldLeaf& leaf, const SurfaceInfo& s,
                              std::vector<std::pair<uint32_t, float>>& out) const {
  out.clear();
  const auto* blob = dynamic_cast<const Blob*>(&leaf.instance->shape());
  if (!blob) return;
  thread_local std::vector<double> fields;
  blob->componentFields(s.pObject, fields);
  double sum = 0.0;
  for (double f : fields) sum += f;
  if (!(sum > 0.0)) return;
  const std::vector<uint32_t>& materials = *leaf.componentMaterials;
  for (size_t k = 0; k < fields.size() && k < materials.size(); ++k) {
    const auto w = static_cast<float>(fields[k] / sum);
    if (!(fields[k] > 0.0) || w < settings_.minWeight) continue;
    auto same = std::find_if(out.begin(), out.end(),
                             [&](const auto& e) { return e.first == materials[k]; });
    if (same != out.end()) same->second += w;
    else out.emplace_back(materials[k], w);
  }
}

Tracer::Shaded Tracer::shadeComponents(const Hit& h, int depth, const Color& weight,
                                       const MediaStack& media, PathSeed& seed,
                                       TraceContext& context) const {
  thread_local std::vector<std::pair<uint32_t, float>> weights;
  componentWeights(h.leaf, h.s, weights);
  // Copied: the shading below may trace rays that hit this blob again.
  const std::vector<std::pair<uint32_t, float>> parts = weights;
  Shaded out;
  out.beyond = media;
  for (const auto& [slot, w] : parts)
    out.result += w * shadeSlot(slot, h, depth, weight, media, seed, context, false).result;
  return out;
}

// A multi-textured blob's share: its materials' shares, weighted as its surface's colour.
Color Tracer::componentsLetThrough(const WorldLeaf& leaf, const SurfaceInfo& s) const {
  std::vector<std::pair<uint32_t, float>> weights;
  componentWeights(leaf, s, weights);
  Color blend(0.0f);
  for (const auto& [slot, w] : weights) blend += w * letThrough(slot, leaf, s);
  return blend;
}

Color Tracer::letThrough(uint32_t slot, const WorldLeaf& leaf, const SurfaceInfo& s) const {
  const SurfaceSlots::Slot& at = slots_[slot];
  switch (at.kind) {
    case SurfaceSlots::Kind::plain: {
      const Material& own = *at.material;
      return seeThrough_[slot]
                 ? transmittedThrough(own, textures_.evalPigment(slot, own, s, *leaf.instance))
                 : own.transmissive;
    }
    case SurfaceSlots::Kind::layers: {
      Color t(1.0f);
      for (uint32_t k = 0; k < at.count && maxComponent(glm::abs(t)) > 0.0f; ++k)
        t *= letThrough(at.first + k, leaf, s);
      return t;
    }
    case SurfaceSlots::Kind::map: {
      const Material& m = *at.material;
      SurfaceInfo moved;
      const SurfaceInfo& e = mapEntrySurface(m.mapPattern, s, moved);
      if (mapAverages(m)) {
        Color t(0.0f);
        float total = 0.0f;
        for (uint32_t k = 0; k < at.count; ++k) {
          const auto w = static_cast<float>(m.mapEntries[k].at);
          t += w * letThrough(at.first + k, leaf, e);
          total += w;
        }
        return t / total;
      }
      const MapBlend b = mapChoice(m, s, *leaf.instance);
      Color t = b.wa * letThrough(at.first + b.a, leaf, e);
      if (b.b != b.a && b.wb > 0.0f) t += b.wb * letThrough(at.first + b.b, leaf, e);
      return t;
    }
  }
  return Color(0.0f);
}

Color Tracer::escaped(const Ray& ray, const MediaStack& media) const {
  Color background = sky_ ? skyColor(*sky_, ray.d, settings_.background) : settings_.background;
  if (const Material* medium = media.top(); medium && medium->attenuates())
    background *= interiorAttenuation(*medium, kInf, false);
  if ((!fogs_.empty() || !rainbows_.empty()) && media.allHollow()) {
    const Vec3 dir = glm::normalize(ray.d);
    // The rainbows first, then the fogs, as POV-Ray applies them.
    if (!rainbows_.empty()) background = rainbowsAlong(rainbows_, dir, kInf).apply(background);
    if (!fogs_.empty()) background = fogsAlong(fogs_, ray.o, dir, kInf).apply(background);
  }
  return background;
}

void Tracer::travelled(const Ray& ray, double t, const Material* leaving, const MediaStack& media,
                       Color& sum, Color& throughput) const {
  // Rainbows, then fog, over the stretch, if it ran outside every solid or inside hollow
  // ones only (MediaStack::fogStretch; render/rainbow.h, render/fog.h): the colour C beyond
  // becomes keep·C + add.
  if ((!fogs_.empty() || !rainbows_.empty()) && media.fogStretch(leaving)) {
    const double speed = glm::length(ray.d);
    const Vec3 dir = ray.d / speed;
    Color keep(1.0f), add(0.0f);
    if (!rainbows_.empty()) {
      const RainbowEffect rainbow = rainbowsAlong(rainbows_, dir, t * speed);
      keep = rainbow.keep;
      add = rainbow.add;
    }
    if (!fogs_.empty()) {
      const FogEffect fog = fogsAlong(fogs_, ray.o, dir, t * speed);
      add = fog.keep * add + fog.add;
      keep *= fog.keep;
    }
    sum += throughput * add;
    throughput *= keep;
  }
  // The stretch lies inside the solid being left, or else in the innermost medium the
  // ray is known to be in.
  const Material* segment = leaving ? leaving : media.top();
  if (segment && segment->attenuates() && !segment->fadeOnExit)
    throughput *= interiorAttenuation(*segment, t * glm::length(ray.d), false);
}

// The shading normal follows the geometric one's side; if interpolation still leaves it
// facing away, the geometric normal is used instead. Then the material's normal pattern
// and bump map.
Vec3 Tracer::shadingNormal(const WorldLeaf& leaf, const SurfaceInfo& s, bool front, const Vec3& v,
                           Vec3& unbent) const {
  const Material& m = *leaf.material;
  const Vec3 ng = front ? s.ng : -s.ng;
  Vec3 n = front ? s.ns : -s.ns;
  if (glm::dot(n, v) <= 0.0) n = ng;
  unbent = n;
  if (m.normal) n = perturbedShadingNormal(*m.normal, leaf.instance->transform(), s, n, v);
  if (m.bumpMap)
    n = bumpedShadingNormal(*textures_.bumpMap(leaf.materialIndex), *m.bumpMap,
                            leaf.instance->transform(), s, n, v);
  if (patternSurface_ && (m.normal || m.bumpMap)) bendPatternSurface(n);
  return n;
}

// What reflect-metallic tints the mirror ray by (render/finish.h); only looked up for it.
Color Tracer::reflectionTint(const WorldLeaf& leaf, const SurfaceInfo& s) const {
  const Material& m = *leaf.material;
  if (!(m.reflectMetallic > 0.0)) return Color(1.0f);
  Color texture(1.0f);
  if (m.hasTexture()) texture = textures_.eval(leaf.materialIndex, m, s, *leaf.instance);
  return metallicBase(m, texture);
}

// k_e + k_a·I_La (·k_t inside an object) + direct light.
Color Tracer::localLight(const WorldLeaf& leaf, const SurfaceInfo& s, const Vec3& n, const Vec3& v,
                         bool leaving, const MediaStack& media, PathSeed& seed,
                         TraceContext& context) const {
  const Material& m = *leaf.material;
  Color local = m.emissive;
  Color texture(1.0f);
  if (m.hasTexture()) texture = textures_.eval(leaf.materialIndex, m, s, *leaf.instance);
  const Color kd = m.diffuse * texture;
  Color ambient =
      (m.hasTexture() && m.ambientIsScalar ? m.ambient * texture : m.ambient) * settings_.ambient;
  if (leaving && !m.innerAmbient) ambient *= m.transmissive;
  local += ambient;
  if (!lights_.empty() && (anyNonZero(kd) || m.hasHighlight())) {
    const Color metal = m.metallic ? metallicBase(m, texture) : kd;
    local += directLight(s, n, v, kd, metal, m, leaf, media, seed, context);
    ++seed.event;
  }
  return local;
}

Tracer::Interface Tracer::interfaceAt(const Material& m, const Color& transmits, const Hit& h,
                                      const MediaStack& media) const {
  Interface side{1.0, 1.0, media, std::nullopt};
  // Only a material that transmits or splits by Fresnel needs the indices.
  if (!anyNonZero(transmits) && !(m.fresnel && (anyPositive(m.reflective) || m.reflectiveMin)))
    return side;
  if (!h.medium) {  // a thin sheet: no medium to enter
    side.n1 = media.ior();
    side.n2 = m.ior;
  } else if (!h.leaving) {
    side.n1 = media.ior();
    side.n2 = h.medium->ior;
    side.beyond.push(h.medium);
  } else {
    side.n1 = h.medium->ior;
    side.beyond.remove(h.medium);
    side.n2 = side.beyond.ior();
    // POV-Ray's Fresnel ratio on leaving while inside another solid too: the last medium
    // entered (this one, when nested) over this one.
    if (!m.nestedExitFresnel && media.size() > 1)
      side.fresnel = FresnelIndices{h.medium->ior, media.ior()};
  }
  return side;
}

Color Tracer::withBranches(Color result, const SurfaceInfo& s, const Vec3& mirror,
                           const SecondaryRays& rays, int depth, const Color& weight,
                           const MediaStack& media, const MediaStack& beyond, PathSeed& seed,
                           TraceContext& context) const {
  // A negative k_t (POV-Ray's transmit -1) subtracts what the ray sees; its weight is the size.
  if (anyNonZero(rays.transmitted) && !rays.straight) {
    Color w = weight * glm::abs(rays.transmitted);
    if (depth < settings_.maxDepth && maxComponent(w) >= settings_.minWeight) {
      ++context.stats.refracted;
      result += rays.transmitted * trace(spawnRay(s, rays.refracted, settings_.epsilon), depth + 1,
                                         w, beyond, seed, context);
    }
  }
  if (anyPositive(rays.mirror)) {
    Color w = weight * rays.mirror;
    if (depth < settings_.maxDepth && maxComponent(w) >= settings_.minWeight) {
      ++context.stats.reflected;
      const bool wasReflected = context.reflected;
      context.reflected = true;
      Color seen =
          trace(spawnRay(s, mirror, settings_.epsilon), depth + 1, w, media, seed, context);
      context.reflected = wasReflected;
      // POV-Ray's reflection exponent.
      if (rays.mirrorPower != 1.0)
        seen = glm::pow(glm::max(seen, Color(0.0f)), Color(static_cast<float>(rays.mirrorPower)));
      result += rays.mirror * seen;
    }
  }
  return result;
}

Color Tracer::directLight(const SurfaceInfo& s, const Vec3& n, const Vec3& v, const Color& kd,
                          const Color& metal, const Material& m, const WorldLeaf& leaf,
                          const MediaStack& media, PathSeed& seed, TraceContext& context) const {
  Color sum(0.0f);
  const bool doubleIlluminate = leaf.doubleIlluminate;
  for (size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = lights_[i];
    if (!leaf.litBy(light)) continue;
    const LightIncidence in = lightIncidence(light, s.p);
    if (!anyNonZero(in.radiance)) continue;  // a negative light darkens (POV-Ray's)
    // A light behind: no diffuse, no highlight, unless the surface is lit from both sides.
    if (!doubleIlluminate && glm::dot(n, in.toLight) <= 0.0) continue;
    Color brdf =
        surfaceResponse(m, kd, metal, ShadingPoint{s.p, n, v}, in.toLight, light.highlights);
    if (!anyNonZero(brdf)) continue;
    Color shadow(1.0f);
    if (light.shadows || light.projectedThrough) {
      shadow = shadowFactor(light, static_cast<uint32_t>(i), in, s, media, seed, context);
      if (!anyNonZero(shadow)) continue;
    }
    // POV-Ray's crand: a light that reaches the point loses a random share of its diffuse
    // term (random per point and light, here a hash of both, so images repeat).
    if (m.crand > 0.0) brdf -= kd * static_cast<float>(m.crand * grain(s.p, i));
    sum += shadow * in.radiance * brdf;
  }
  return sum;
}

Color Tracer::shadowFactor(const Light& light, uint32_t lightIndex, const LightIncidence& in,
                           const SurfaceInfo& s, const MediaStack& media, const PathSeed& seed,
                           TraceContext& context) const {
  RayStats& stats = context.stats;
  // The object that blocked this light's last shadow ray is asked first.
  World::ObjectId& lastBlocker = context.shadowCache.slot(cacheOwner_, lightIndex, lights_.size());
  const bool fogged = light.mediaAttenuation && !fogs_.empty();
  const Shape* through = world_.projection(lightIndex);
  auto shadowRay = [&](Ray ray) {
    if (through) {
      // POV-Ray's projected_through: dark unless the ray meets the objects before the
      // light; then only what lies nearer than that meeting, by POV-Ray's SMALL_TOLERANCE
      // in world units, shadows the point (its TracePointLightShadowRay).
      lucent::Hit meeting;
      ++stats.queries;
      if (!through->intersect(ray, meeting)) return Color(0.0f);
      if (!light.shadows) return Color(1.0f);
      ray.tmax = meeting.t - kProjectionTolerance / glm::length(ray.d);
      if (!(ray.tmax > ray.tmin)) return Color(1.0f);
    }
    Color passed;
    if (anyTransmissive_) {
      passed = transmittance(ray, media, lastBlocker, stats);
    } else {
      // An opaque scene: one any-hit query, nothing to copy.
      ++stats.shadow;
      passed = blockedByOpaque(ray, lastBlocker, stats) ? Color(0.0f) : Color(1.0f);
    }
    if (fogged && anyNonZero(passed)) passed *= fogKeptAlongShadowRay(ray, media, stats);
    return passed;
  };
  if (in.parallel) {
    // Along the light's rays: to infinity, or as far as the light lies (its plane).
    if (std::isinf(in.distance)) return shadowRay(spawnRay(s, in.toLight, settings_.epsilon));
    return shadowRay(spawnRayTo(s, s.p + in.toLight * in.distance, settings_.epsilon));
  }
  const ShadowRays rays(s, settings_.epsilon);
  const std::vector<Vec3>& fixed = fixedTargets_[lightIndex];
  // An oriented light turns to face the point: its axes here, once for all its samples.
  const AreaAxes axes = fixed.empty() ? areaAxes(light, s.p) : AreaAxes{light.u, light.v};
  auto sampleRay = [&](int k) {
    Vec3 target;
    if (!fixed.empty()) {
      target = fixed[k];
    } else if (!light.jitter) {
      target = lightSamplePoint(light, axes, k, Vec2(0.5));
    } else {
      // Deterministic: a hash of the pixel, sample, shading event, light and grid point.
      uint64_t path = (uint64_t(seed.sample) << 32) | seed.event;
      uint64_t which = (uint64_t(lightIndex) << 32) | uint32_t(k);
      Vec2 jitter(hashToUnit(seed.x, seed.y, path, 2 * which),
                  hashToUnit(seed.x, seed.y, path, 2 * which + 1));
      target = lightSamplePoint(light, axes, k, jitter);
    }
    return shadowRay(rays.to(target));
  };
  if (light.type == LightType::Area && light.adaptive) {
    const int nu = std::max(light.samplesU, 2), nv = std::max(light.samplesV, 2);
    return context.areaSampler.average(nu, nv, *light.adaptive, in.radiance,
                                       [&](int a, int b) { return sampleRay(b * nu + a); });
  }
  const int count = shadowSampleCount(light);
  // One sample (a point or spot light): no average to take. The average's division, done
  // by the compiler as a vector division over the colour's lanes, drew 72 % of this
  // function's profile samples and 9 % of a render's (docs/performance.md, "before and after").
  if (count == 1) return sampleRay(0);
  Color sum(0.0f);
  for (int k = 0; k < count; ++k) sum += sampleRay(k);
  return sum / static_cast<float>(count);
}

bool Tracer::blockedByOpaque(const Ray& ray, World::ObjectId& lastBlocker, RayStats& stats) const {
  ++stats.queries;
  const World::ObjectId blocker = world_.opaqueOccluder(ray, lastBlocker);
  // Unblocked: the slot keeps its object, the next ray may need it.
  if (blocker == World::kNoObject) return false;
  if (blocker == lastBlocker) ++stats.shadowCacheHits;
  else lastBlocker = blocker;
  return true;
}

Color Tracer::transmittance(Ray ray, MediaStack media, RayStats& stats) const {
  World::ObjectId none = World::kNoObject;
  return transmittance(ray, std::move(media), none, stats);
}

// POV-Ray's media_attenuation: each stretch between the transparent surfaces the shadow ray
// crosses is dimmed by the fogs if it runs outside all solids or inside hollow ones only,
// as a camera ray's stretch; fog adds no colour to light.
Color Tracer::fogKeptAlongShadowRay(Ray ray, MediaStack media, RayStats& stats) const {
  const double speed = glm::length(ray.d);
  const Vec3 dir = ray.d / speed;
  Color kept(1.0f);
  auto stretch = [&](double from, double to, const Material* leaving) {
    if (!media.fogStretch(leaving)) return;
    const double length = std::isinf(to) ? kInf : (to - from) * speed;
    kept *= fogsAlong(fogs_, ray.o + ray.d * from, dir, length).keep;
  };
  double from = ray.tmin;
  if (anyTransmissive_) {
    for (;;) {
      WorldHit hit;
      ++stats.queries;
      if (!world_.intersectTransmissive(ray, hit)) break;
      const WorldLeaf& leaf = hit.leaf();
      const bool front = !leaf.medium || !(glm::dot(ray.d, hit.surface(ray).ng) > 0.0);
      const MediumCrossing c = mediumCrossing(leaf, hit.hit.flip, front, media);
      stretch(from, hit.t(), c.leaving ? c.medium : nullptr);
      if (c.medium) {
        if (c.leaving) media.remove(c.medium);
        else media.push(c.medium);
      }
      from = hit.t();
      ray.tmin = hit.t();
    }
  }
  stretch(from, ray.tmax, nullptr);
  return kept;
}

Color Tracer::transmittance(Ray ray, MediaStack media, World::ObjectId& lastBlocker,
                            RayStats& stats) const {
  ++stats.shadow;
  // Any opaque object in the way blocks the light, whatever else the ray crosses.
  if (blockedByOpaque(ray, lastBlocker, stats)) return Color(0.0f);
  if (!anyTransmissive_) return Color(1.0f);
  // Only the objects that may transmit remain: their surfaces in order.
  Color t(1.0f);
  const double speed = glm::length(ray.d);  // world distance per unit of t
  double tPrevious = ray.tmin;
  for (;;) {
    WorldHit hit;
    ++stats.queries;
    if (!world_.intersectTransmissive(ray, hit)) break;
    WorldLeaf inner;
    const WorldLeaf& leaf = surfaceLeaf(hit.leaf(), ray, hit, inner);
    if (!leaf.transmissive) return Color(0.0f);
    if (!leaf.componentMaterials && slots_[leaf.materialIndex].kind == SurfaceSlots::Kind::plain &&
        !seeThrough_[leaf.materialIndex])
      t *= leaf.material->transmissive;
    else {
      const SurfaceInfo s = hit.surface(ray);
      PatternSurface surface;
      if (patternSurface_) surface = patternSurfaceAt(s, -glm::normalize(ray.d));
      const PatternSurfaceScope surfaceScope(patternSurface_, surface);
      t *= leaf.componentMaterials ? componentsLetThrough(leaf, s)
                                   : letThrough(leaf.materialIndex, leaf, s);
    }
    if (anyAbsorbing_) {
      const bool front = !leaf.medium || !(glm::dot(ray.d, hit.surface(ray).ng) > 0.0);
      const MediumCrossing c = mediumCrossing(hit.leaf(), hit.hit.flip, front, media);
      const Material* segment = c.leaving ? c.medium : media.top();
      if (segment && segment->attenuates())
        t *= interiorAttenuation(*segment, (hit.t() - tPrevious) * speed, true);
      if (c.medium) {
        if (c.leaving) media.remove(c.medium);
        else media.push(c.medium);
      }
    }
    if (!anyNonZero(t)) return Color(0.0f);
    // The same ray searched again beyond this hit: t is strictly increasing, and the
    // hit just found is excluded because the search interval is open.
    tPrevious = hit.t();
    ray.tmin = hit.t();
  }
  if (anyAbsorbing_) {
    if (const Material* medium = media.top(); medium && medium->attenuates())
      t *= interiorAttenuation(*medium, (ray.tmax - tPrevious) * speed, true);
  }
  return t;
}

}  // namespace lucent
