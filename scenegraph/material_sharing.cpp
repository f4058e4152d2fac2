#include "material_sharing.h"

#include <functional>
#include <tuple>
#include <utility>

namespace lucent {

// Every term of Material below is compared. A term added to Material must be added here
// too, or two materials that differ in it would be shared: the size is checked so that
// adding one stops the build here.
static_assert(sizeof(Material) == 2976,
              "Material changed: add its new terms to terms() in material_sharing.cpp, then "
              "update this size");

namespace {

auto terms(const Material& m) {
  return std::tie(
      m.id, m.emissive, m.ambient, m.ambientIsScalar, m.diffuse, m.specular, m.shininess, m.phong,
      m.phongSize, m.brilliance, m.crand, m.metallic, m.metallicAmount, m.metallicColor,
      m.reflectMetallic, m.innerAmbient, m.nestedExitFresnel, m.reflective, m.transmissive, m.ior,
      m.fresnel, m.reflectiveMin, m.reflectFalloff, m.reflectExponent, m.fresnelTransmission,
      m.conserveEnergy, m.absorption, m.fadeDistance, m.fadePower, m.fadeColor, m.fadeOnExit,
      m.fullTir, m.hollow, m.irid, m.iridThickness, m.iridTurbulence, m.iridLeftHanded);
}

void mix(size_t& h, float v) { h = h * 1000003u ^ std::hash<float>()(v); }

size_t hashOf(const Material& m) {
  size_t h = std::hash<std::string>()(m.id);
  for (const Color* c :
       {&m.ambient, &m.diffuse, &m.specular, &m.phong, &m.reflective, &m.transmissive, &m.emissive})
    for (int i = 0; i < 3; ++i) mix(h, (*c)[i]);
  return h;
}

}  // namespace

bool plainMaterial(const Material& m) {
  return std::holds_alternative<std::monostate>(m.texture) && m.layers.empty() &&
         std::holds_alternative<std::monostate>(m.mapPattern) && m.mapEntries.empty() &&
         !m.normal && !m.bumpMap;
}

bool samePlainMaterial(const Material& a, const Material& b) {
  return plainMaterial(a) && plainMaterial(b) && terms(a) == terms(b);
}

uint32_t MaterialSharing::add(std::vector<Material>& materials, Material m) {
  if (!plainMaterial(m)) {
    materials.push_back(std::move(m));
    return static_cast<uint32_t>(materials.size() - 1);
  }
  std::vector<uint32_t>& same = byHash_[hashOf(m)];
  for (uint32_t i : same)
    if (samePlainMaterial(materials[i], m)) return i;
  same.push_back(static_cast<uint32_t>(materials.size()));
  materials.push_back(std::move(m));
  return same.back();
}

}  // namespace lucent
