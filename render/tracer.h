// The Whitted integrator: the colour seen along a ray, with the contract's shading
//   I = k_e + k_a·I_La + Σ_lights A_shadow·A_dist·I_L·[k_d (N·L) + k_s (N·H)^n_s]
//       + k_r·I_reflected + k_t·I_transmitted
// plus recursion limits (max-depth, min-weight), nested media and Beer–Lambert absorption.
#pragma once

#include "finish.h"
#include "light_sample.h"
#include "media_stack.h"
#include "medium_crossing.h"
#include "ray_stats.h"
#include "shadow_cache.h"
#include "surface_slots.h"
#include "texture.h"
#include "trace_context.h"

#include "primitives/hit.h"
#include "scenegraph/world.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace lucent {

// Where a path comes from: the pixel, the sample and a count of the shading events so
// far, the only inputs of the tracer's pseudo-random numbers (area-light jitter), so a
// pixel's colour never depends on the thread that renders it.
struct PathSeed {
  uint32_t x = 0, y = 0, sample = 0;
  uint32_t event = 0;
};

class Tracer {
 public:
  // Reads the render settings, lights and materials from world.scene() and loads the
  // image textures (throws LocatedError), through `textures` if given. The world must
  // outlive the tracer.
  explicit Tracer(const World& world, ImageMapCache* textures = nullptr);

  // The colour seen along a camera ray (depth 1, weight 1) that starts in `media`, with
  // the calling thread's context (its counts, shadow cache and scratch).
  Color traceCamera(const Ray& ray, const MediaStack& media, PathSeed& seed,
                    TraceContext& context) const;

  // The media containing point p (a camera's starting media): the media of the top-level
  // solids whose inside() holds p (WorldObject::medium), the largest bounding box outermost
  // (an infinite plane is outermost).
  MediaStack mediaAt(const Vec3& p) const;

  // Fraction of light that passes along the shadow ray (t in (ray.tmin, ray.tmax)),
  // which starts in `media`: 0 if it crosses an opaque surface, else k_t for every
  // transparent one, times exp(−absorption·d) for each stretch inside an absorbing solid.
  // It uses no shadow cache.
  Color transmittance(Ray ray, MediaStack media, RayStats& stats) const;
  // transmittance() with a light's slot of a shadow cache (POV-Ray's): the
  // opaque object that blocked the light's last shadow ray is tested first, and the new
  // blocker stored there. The opaque objects are asked first, by one any-hit query
  // (World::opaqueOccluder); only a ray that none blocks walks the surfaces of the
  // objects that may transmit, in order (World::intersectTransmissive), as a scene
  // without opaque objects would. The answer is the walk's through every object, except
  // that an opaque surface crossed at the very same t as a transparent one now blocks
  // (the walk through every object resumed beyond that t and could skip it).
  Color transmittance(Ray ray, MediaStack media, World::ObjectId& lastBlocker,
                      RayStats& stats) const;

 private:
  Color trace(Ray ray, int depth, Color weight, MediaStack media, PathSeed& seed,
              TraceContext& context) const;

  // One surface hit as trace() shades it: the colour it sends back along the ray
  // (its own light and its branches), its secondary rays and the media beyond it.
  struct Hit {
    const WorldLeaf& leaf;
    const SurfaceInfo& s;
    Vec3 v;  // towards the viewer
    bool front = true;
    bool leaving = false;  // the ray was inside `medium`
    // The medium the ray leaves or enters here (render/medium_crossing.h); null: a
    // surface without an inside.
    const Material* medium = nullptr;
    // fade-on-exit: the attenuation of the stretch inside, for the rays leaving here.
    Color passOut{1.0f};
  };
  struct Shaded {
    Color result{0.0f};
    SecondaryRays rays;
    MediaStack beyond;
  };
  // The surface of slot `slot` (render/surface_slots.h) at the hit, by its kind.
  // `mayContinue`: a transmitted ray that goes on unbent is left to trace()'s loop (in
  // Shaded::rays); otherwise it is traced here, as a bent one is (a map's entries).
  Shaded shadeSlot(uint32_t slot, const Hit& h, int depth, const Color& weight,
                   const MediaStack& media, PathSeed& seed, TraceContext& context,
                   bool mayContinue) const;
  // A material of one layer (see-through where its texture is).
  Shaded shadeOne(uint32_t slot, const Hit& h, int depth, const Color& weight,
                  const MediaStack& media, PathSeed& seed, TraceContext& context,
                  bool mayContinue) const;
  // A layered material, as POV-Ray composes its layers: each layer's own light dimmed by
  // what the layers above let through, each layer's mirror ray added as it is, the light
  // from behind through all of them along the top layer's refracted ray.
  Shaded shadeLayers(const SurfaceSlots::Slot& layers, const Hit& h, int depth, const Color& weight,
                     const MediaStack& media, PathSeed& seed, TraceContext& context,
                     bool mayContinue) const;
  // A material map: the one or two entries the pattern's value falls between, each shaded
  // whole, their colours blended by weight (POV-Ray's texture_map).
  Shaded shadeMap(const SurfaceSlots::Slot& map, const Hit& h, int depth, const Color& weight,
                  const MediaStack& media, PathSeed& seed, TraceContext& context) const;
  // An average of materials: every entry shaded whole at the map's weight, the colours
  // averaged by the entries' weights (POV-Ray's average of textures). `h` holds the
  // entries' point (render/map_entries.h).
  Shaded shadeAverage(const SurfaceSlots::Slot& map, const Hit& h, int depth, const Color& weight,
                      const MediaStack& media, PathSeed& seed, TraceContext& context) const;
  // What the surface of slot `slot` lets through at a hit (a shadow ray's share): k_t, or a
  // see-through texture's, the product over layers, the blend over a map's entries (the
  // weighted mean over an average's).
  Color letThrough(uint32_t slot, const WorldLeaf& leaf, const SurfaceInfo& s) const;
  // A blob whose components have materials of their own (WorldLeaf::componentMaterials):
  // POV-Ray's weights at the hit, each component's |field| over their sum, those below
  // the bail-out weight left out (as POV-Ray skips them), summed per material (slot, weight).
  void componentWeights(const WorldLeaf& leaf, const SurfaceInfo& s,
                        std::vector<std::pair<uint32_t, float>>& out) const;
  // Such a blob's surface: each material shaded whole with the ray's weight, the colours
  // summed by the weights (POV-Ray's multi-textured blob).
  Color componentsLetThrough(const WorldLeaf& leaf, const SurfaceInfo& s) const;
  Shaded shadeComponents(const Hit& h, int depth, const Color& weight, const MediaStack& media,
                         PathSeed& seed, TraceContext& context) const;
  // `leaf` as the surface of slot `slot` (itself when the slot is its material's).
  WorldLeaf leafOfSlot(const WorldLeaf& leaf, uint32_t slot) const;
  // The slot of the surface `ray` meets at s: the leaf's interior material where it meets
  // the surface from inside, else its material.
  static uint32_t surfaceSlot(const WorldLeaf& leaf, const Ray& ray, const SurfaceInfo& s);
  // The leaf as the surface a shadow ray meets at the hit: itself, or its interior
  // material's (written to `inner`) where the ray comes from inside.
  const WorldLeaf& surfaceLeaf(const WorldLeaf& leaf, const Ray& ray, const WorldHit& hit,
                               WorldLeaf& inner) const;

  // The parts of one step of trace(), in the order it takes them.
  // The colour of a ray that hits nothing: the sky or background, through the medium the
  // ray is in (absorbed over an infinite stretch) and the fog.
  Color escaped(const Ray& ray, const MediaStack& media) const;
  // The stretch of `ray` up to t: fog (added to sum, kept in throughput) and absorption
  // (kept in throughput). `leaving`: the solid the ray was inside, if it is leaving one.
  void travelled(const Ray& ray, double t, const Material* leaving, const MediaStack& media,
                 Color& sum, Color& throughput) const;
  // The normal shading uses at surface s of `leaf`, facing the viewer (direction v).
  // Also returns, in `unbent`, the normal before the material's <normal> or <bump-map>.
  Vec3 shadingNormal(const WorldLeaf& leaf, const SurfaceInfo& s, bool front, const Vec3& v,
                     Vec3& unbent) const;
  // The colour reflect-metallic tints the mirror ray by at s (1 without it).
  Color reflectionTint(const WorldLeaf& leaf, const SurfaceInfo& s) const;
  // The surface's own light: emission, ambient and the lights' direct light.
  Color localLight(const WorldLeaf& leaf, const SurfaceInfo& s, const Vec3& n, const Vec3& v,
                   bool leaving, const MediaStack& media, PathSeed& seed,
                   TraceContext& context) const;
  // The indices of refraction on the viewer's side and beyond a surface, and the media
  // beyond it (both indices 1 for a material that neither transmits nor splits by Fresnel).
  // `transmits`: what m lets through at this point (its k_t, or a see-through texture's);
  // the hit's medium is left or entered as h says.
  struct Interface {
    double n1 = 1.0, n2 = 1.0;
    MediaStack beyond;
    // The indices of the Fresnel split, where not n1 and n2 (Material::nestedExitFresnel).
    std::optional<FresnelIndices> fresnel;
    FresnelIndices fresnelPair() const { return fresnel.value_or(FresnelIndices{n1, n2}); }
  };
  Interface interfaceAt(const Material& m, const Color& transmits, const Hit& h,
                        const MediaStack& media) const;
  // `result` plus the bent transmitted ray and the mirror ray, each traced one level
  // deeper when its weight and the depth allow.
  // `mirror`: the mirror ray's unit direction.
  Color withBranches(Color result, const SurfaceInfo& s, const Vec3& mirror,
                     const SecondaryRays& rays, int depth, const Color& weight,
                     const MediaStack& media, const MediaStack& beyond, PathSeed& seed,
                     TraceContext& context) const;
  // Σ over lights of A_shadow·A_dist·I_L·[k_d (N·L) + k_s (N·H)^n_s].
  // The lights that light `leaf` (its light group's, scenegraph/light_group.h); with its
  // double-illuminate, lights behind the surface count too.
  Color directLight(const SurfaceInfo& s, const Vec3& n, const Vec3& v, const Color& kd,
                    const Color& metal, const Material& m, const WorldLeaf& leaf,
                    const MediaStack& media, PathSeed& seed, TraceContext& context) const;
  // A_shadow of one light at s: the transmittance averaged over the light's samples
  // (an adaptive area light: the context's AdaptiveAreaSampler's estimate of it), with
  // the light's slot of the context's shadow cache.
  Color shadowFactor(const Light& light, uint32_t lightIndex, const LightIncidence& in,
                     const SurfaceInfo& s, const MediaStack& media, const PathSeed& seed,
                     TraceContext& context) const;
  // What the fogs keep of a light along a shadow ray that starts in `media` (its light
  // has media-attenuation): the product over its stretches outside solids or inside
  // hollow ones only.
  Color fogKeptAlongShadowRay(Ray ray, MediaStack media, RayStats& stats) const;
  // Whether an opaque object blocks the ray (one any-hit query; updates lastBlocker).
  bool blockedByOpaque(const Ray& ray, World::ObjectId& lastBlocker, RayStats& stats) const;

  const World& world_;
  const RenderSettings settings_;        // a copy: the scene may change after the renderer is built
  const std::vector<Light> lights_;      // a copy, as the settings
  const std::optional<Sky> sky_;         // a copy, as the settings
  const std::vector<Fog> fogs_;          // a copy; none: no per-ray cost but this test
  const std::vector<Rainbow> rainbows_;  // a copy; none: no per-ray cost but this test
  // Each light's shadow-ray targets when they are fixed (lightSamplePoint without
  // jitter), computed once: the loop over an area light's 64 samples then only reads
  // them. Empty for a jittered or oriented area light, whose targets differ per point.
  std::vector<std::vector<Vec3>> fixedTargets_;
  SurfaceSlots slots_;            // the materials and their layers, by slot
  TextureSet textures_;           // by slot
  std::vector<char> seeThrough_;  // per slot: textureSeeThrough (evaluated per hit)
  bool anyTransmissive_ = false;  // else shadow rays ask only the any-hit question
  bool anyAbsorbing_ = false;     // else shadow rays need no media bookkeeping
  bool patternSurface_ =
      false;  // some pattern reads the surface (render/patterns/pattern_surface.h)
  // What this tracer's entries in a ShadowCache carry (unique in the process). Copies
  // share it, as they share the world whose objects the cached ids name.
  uint64_t cacheOwner_ = newShadowCacheOwner();
};

}  // namespace lucent
