// The surfaces a tracer shades, by slot. Slot i, below the number of materials, is material
// i. A layered material's layers and a material map's entries get slots of their own after
// those: a layer is a material of one layer (its own terms as the bottom one, then each
// <layer>), an entry whatever its surface is (one layer, layers, or a map again), and each
// carries the whole material's interior terms (ior, fade, absorption, hollow, full-tir,
// inner-ambient), so that it is shaded as a material of its own.
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

  enum class Kind : uint8_t {
    plain,   // a material of one layer: `material` is shaded as it is
    layers,  // children: the layers, the top one first
    map,     // children: the map's entries in order; `material` holds the map
  };
  struct Slot {
    const Material* material = nullptr;
    Kind kind = Kind::plain;
    uint32_t first = 0;  // the children's slots: first, first + 1, ...
    uint32_t count = 0;
  };
  const Slot& operator[](uint32_t slot) const { return slots_[slot]; }
  uint32_t size() const { return static_cast<uint32_t>(slots_.size()); }
  // Every slot's material (a layer's copy, a map's entries' copies), by slot.
  std::vector<const Material*> materials() const;

 private:
  // Fills slot `at` with `m` (a copy carrying `whole`'s interior unless it is a scene
  // material), and its children after the slots taken so far.
  void fill(uint32_t at, const Material& m, const Material& whole, bool isScene);

  std::deque<Material> copies_;  // the layers' and entries' materials (addresses kept)
  std::vector<Slot> slots_;
};

}  // namespace lucent
