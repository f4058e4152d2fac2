#include "surface_slots.h"

namespace lucent {

namespace {

// A layer as a material of its own: its surface terms and the whole material's interior.
Material layerMaterial(const Material& layer, const Material& whole) {
  Material m = layer;
  m.layers.clear();
  m.ior = whole.ior;
  m.fullTir = whole.fullTir;
  m.absorption = whole.absorption;
  m.fadeDistance = whole.fadeDistance;
  m.fadePower = whole.fadePower;
  m.fadeColor = whole.fadeColor;
  m.hollow = whole.hollow;
  m.innerAmbient = whole.innerAmbient;
  return m;
}

}  // namespace

SurfaceSlots::SurfaceSlots(const std::vector<Material>& materials) {
  for (const Material& m : materials) slots_.push_back(&m);
  layers_.resize(materials.size());
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material& whole = materials[i];
    if (!whole.layered()) continue;
    layers_[i] = {static_cast<uint32_t>(slots_.size()),
                  static_cast<uint32_t>(whole.layers.size() + 1)};
    for (auto layer = whole.layers.rbegin(); layer != whole.layers.rend(); ++layer) {
      copies_.push_back(layerMaterial(*layer, whole));
      slots_.push_back(&copies_.back());
    }
    copies_.push_back(layerMaterial(whole, whole));  // the bottom layer: its own terms
    slots_.push_back(&copies_.back());
  }
}

}  // namespace lucent
