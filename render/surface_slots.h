// The surfaces a tracer shades, by slot. Slot i, below the number of materials, is material
// i as the scene holds it. A layered material's layers get slots of their own after those:
// its own terms as the bottom layer and each <layer> over it, each a material of one layer
// that carries the whole material's interior terms (ior, fade, absorption, hollow,
// full-tir, inner-ambient), so that a layer is shaded as a material of its own.
#pragma once

#include "scenegraph/material.h"

#include <cstdint>
#include <deque>
#include <vector>

namespace lucent {

class SurfaceSlots {
 public:
  explicit SurfaceSlots(const std::vector<Material>& materials);
  SurfaceSlots(const SurfaceSlots&) = delete;
  SurfaceSlots& operator=(const SurfaceSlots&) = delete;

  // Every slot's material: the scene's materials, then the layers.
  const std::vector<const Material*>& all() const { return slots_; }

  // The slots of material i's layers, the top one first; count 0 for a material of one
  // layer.
  struct Layers {
    uint32_t first = 0;
    uint32_t count = 0;
  };
  Layers layersOf(uint32_t material) const { return layers_[material]; }

 private:
  std::deque<Material> copies_;  // the layers' materials (a deque keeps their addresses)
  std::vector<const Material*> slots_;
  std::vector<Layers> layers_;
};

}  // namespace lucent
