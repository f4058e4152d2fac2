#include "pov_wave_sources.h"

#include "scenegraph/pigment_function.h"

#include <fmt/core.h>

namespace lucent {

namespace {

// The first count met and the element that holds it, then every other compared with it.
class WaveSourceCounts {
 public:
  explicit WaveSourceCounts(PovIssues& issues) : issues_(issues) {}

  void pattern(const PatternSpec& s, const SourceLoc& loc) {
    if (s.type == PatternType::ripples || s.type == PatternType::waves) {
      if (!first_) {
        first_ = s.waveSources;
        firstLoc_ = loc;
      } else if (*first_ != s.waveSources && !reported_) {
        reported_ = true;
        issues_.error(loc, fmt::format("ripples or waves with {} sources where another has {} "
                                       "(at {}): POV-Ray's number_of_waves is one for the scene",
                                       s.waveSources, *first_, firstLoc_.str()));
      }
    }
    if (s.pigment) texture(s.pigment->texture, loc);
    if (s.function)
      for (const auto& p : s.function->pigments) texture(p->pigment, loc);
  }

  void texture(const Texture& t, const SourceLoc& loc) {
    const std::vector<TextureMapEntry>* entries = nullptr;
    if (const auto* p = std::get_if<PatternTexture>(&t)) {
      pattern(p->pattern, loc);
      entries = &p->pigments;
    } else if (const auto* c = std::get_if<CheckerTexture>(&t)) {
      entries = &c->pigments;
    } else if (const auto* h = std::get_if<HexagonTexture>(&t)) {
      entries = &h->pigments;
    } else if (const auto* b = std::get_if<BrickTexture>(&t)) {
      entries = &b->pigments;
    } else if (const auto* a = std::get_if<AverageTexture>(&t)) {
      entries = &a->entries;
    }
    if (entries)
      for (const TextureMapEntry& e : *entries) texture(e.texture, loc);
  }

  void normal(const NormalSpec& n, const SourceLoc& loc) {
    pattern(n.pattern, loc);
    for (const WeightedNormal& e : n.average) normal(e.normal, loc);
    for (const NormalMapEntry& e : n.map) normal(e.normal, loc);
  }

  void material(const Material& m) {
    texture(m.texture, m.loc);
    if (m.normal) normal(*m.normal, m.loc);
    texture(m.mapPattern, m.loc);
    for (const Material& layer : m.layers) material(layer);
    for (const MaterialMapEntry& e : m.mapEntries) material(e.material);
  }

  std::optional<int> shared() const {
    if (!first_ || *first_ == kDefaultWaveSources) return std::nullopt;
    return first_;
  }

 private:
  PovIssues& issues_;
  std::optional<int> first_;
  SourceLoc firstLoc_;
  bool reported_ = false;
};

}  // namespace

std::optional<int> sharedWaveSources(const Scene& scene, const std::vector<bool>& used,
                                     const Camera& camera, PovIssues& issues) {
  WaveSourceCounts counts(issues);
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (i < used.size() && used[i]) counts.material(scene.materials[i]);
  if (scene.sky)
    for (const Texture& layer : scene.sky->layers) counts.texture(layer, scene.sky->loc);
  if (camera.normal) counts.normal(*camera.normal, camera.loc);
  return counts.shared();
}

}  // namespace lucent
