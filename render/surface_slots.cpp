#include "surface_slots.h"

namespace lucent {

namespace {

// A layer or an entry as a material of its own: its surface and the whole material's
// interior.
Material withInterior(const Material& surface, const Material& whole, bool keepLayers) {
  Material m = surface;
  if (!keepLayers) m.layers.clear();
  m.ior = whole.ior;
  m.fullTir = whole.fullTir;
  m.absorption = whole.absorption;
  m.fadeDistance = whole.fadeDistance;
  m.fadePower = whole.fadePower;
  m.fadeColor = whole.fadeColor;
  m.fadeOnExit = whole.fadeOnExit;
  m.hollow = whole.hollow;
  m.innerAmbient = whole.innerAmbient;
  m.nestedExitFresnel = whole.nestedExitFresnel;
  return m;
}

}  // namespace

SurfaceSlots::SurfaceSlots(const std::vector<Material>& materials) {
  slots_.resize(materials.size());
  for (size_t i = 0; i < materials.size(); ++i)
    fill(static_cast<uint32_t>(i), materials[i], materials[i], true);
}

void SurfaceSlots::fill(uint32_t at, const Material& m, const Material& whole, bool isScene) {
  const Material* own = &m;
  if (!isScene) {
    copies_.push_back(withInterior(m, whole, true));
    own = &copies_.back();
  }
  if (m.mapped()) {
    const auto first = static_cast<uint32_t>(slots_.size());
    const auto count = static_cast<uint32_t>(m.mapEntries.size());
    slots_[at] = {own, Kind::map, first, count};
    slots_.resize(slots_.size() + count);
    for (uint32_t k = 0; k < count; ++k) fill(first + k, own->mapEntries[k].material, whole, false);
  } else if (m.layered()) {
    const auto first = static_cast<uint32_t>(slots_.size());
    const auto count = static_cast<uint32_t>(m.layers.size() + 1);
    slots_[at] = {own, Kind::layers, first, count};
    // The top layer first, the material's own terms (the bottom layer) last.
    for (auto layer = m.layers.rbegin(); layer != m.layers.rend(); ++layer) {
      copies_.push_back(withInterior(*layer, whole, false));
      slots_.push_back({&copies_.back(), Kind::plain, 0, 0});
    }
    copies_.push_back(withInterior(m, whole, false));
    slots_.push_back({&copies_.back(), Kind::plain, 0, 0});
  } else {
    slots_[at] = {own, Kind::plain, 0, 0};
  }
}

std::vector<const Material*> SurfaceSlots::materials() const {
  std::vector<const Material*> out;
  for (const Slot& s : slots_) out.push_back(s.material);
  return out;
}

}  // namespace lucent
