#include "pattern_surface.h"

#include "scenegraph/overloaded.h"

namespace lucent {

namespace {

thread_local PatternSurface* tCurrent = nullptr;

bool readsSurface(const PatternSpec& s);
bool readsSurface(const Texture& t);

bool readsSurface(const std::vector<TextureMapEntry>& entries) {
  for (const TextureMapEntry& e : entries)
    if (readsSurface(e.texture)) return true;
  return false;
}

bool readsSurface(const PatternSpec& s) {
  if (s.type == PatternType::slope) return true;
  return s.pigment && readsSurface(s.pigment->texture);
}

bool readsSurface(const Texture& t) {
  return std::visit(
      Overloaded{[](std::monostate) { return false; }, [](const ImageTexture&) { return false; },
                 [](const PatternTexture& p) {
                   return readsSurface(p.pattern) || readsSurface(p.pigments);
                 },
                 [](const AverageTexture& a) { return readsSurface(a.entries); },
                 [](const auto& block) { return readsSurface(block.pigments); }},
      t);
}

bool readsSurface(const NormalSpec& n) {
  if (readsSurface(n.pattern)) return true;
  for (const WeightedNormal& w : n.average)
    if (readsSurface(w.normal)) return true;
  for (const NormalMapEntry& e : n.map)
    if (readsSurface(e.normal)) return true;
  return false;
}

}  // namespace

const PatternSurface* currentPatternSurface() { return tCurrent; }

void bendPatternSurface(const Vec3& normal) {
  if (tCurrent) tCurrent->normal = normal;
}

PatternSurfaceScope::PatternSurfaceScope(bool active, PatternSurface& surface) : active_(active) {
  if (!active_) return;
  previous_ = tCurrent;
  tCurrent = &surface;
}

PatternSurfaceScope::~PatternSurfaceScope() {
  if (active_) tCurrent = previous_;
}

bool usesPatternSurface(const Material& m) {
  if (readsSurface(m.texture) || readsSurface(m.mapPattern)) return true;
  if (m.normal && readsSurface(*m.normal)) return true;
  for (const Material& layer : m.layers)
    if (usesPatternSurface(layer)) return true;
  for (const MaterialMapEntry& e : m.mapEntries)
    if (usesPatternSurface(e.material)) return true;
  return false;
}

}  // namespace lucent
