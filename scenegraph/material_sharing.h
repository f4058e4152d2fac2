// Equal materials shared by one index: a scene whose loops give thousands of objects the
// same plain colour (POV-Ray's `pigment { color C }` on every sphere of a #while) holds one
// material for them instead of thousands, which the POV-Ray importer otherwise builds,
// stores and copies as the scene grows (docs/performance.md: importing).
#pragma once

#include "material.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace lucent {

// A material of constant terms only: no texture, layers, map, normal or bump map. Only
// these are compared; the others are never shared (their patterns hold transforms that
// rarely repeat exactly).
bool plainMaterial(const Material& m);

// Every term of two plain materials equal (their names too; where they were written is
// not a term).
bool samePlainMaterial(const Material& a, const Material& b);

// The index of an equal plain material already in `materials`, found by a hash of its
// terms, or of `m` appended to them.
class MaterialSharing {
 public:
  uint32_t add(std::vector<Material>& materials, Material m);

 private:
  std::unordered_map<size_t, std::vector<uint32_t>> byHash_;
};

}  // namespace lucent
