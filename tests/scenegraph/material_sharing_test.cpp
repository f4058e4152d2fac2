// Equal plain materials share one index; a material differing in any term, or holding a
// pattern, gets its own.
#include "scenegraph/material_sharing.h"

#include <catch2/catch.hpp>

#include <functional>
#include <utility>
#include <vector>

using namespace lucent;

namespace {

Material plain() {
  Material m;
  m.ambient = Color(0.1f, 0.02f, 0.0f);
  m.diffuse = Color(0.6f, 0.12f, 0.0f);
  return m;
}

}  // namespace

TEST_CASE("material sharing: equal plain materials share an index and any changed term does not",
          "[scenegraph][material]") {
  const std::vector<std::pair<const char*, std::function<void(Material&)>>> changes = {
      {"emissive", [](Material& m) { m.emissive = Color(0.1f); }},
      {"ambient", [](Material& m) { m.ambient.b = 0.5f; }},
      {"ambientIsScalar", [](Material& m) { m.ambientIsScalar = false; }},
      {"diffuse", [](Material& m) { m.diffuse.g = 0.5f; }},
      {"specular", [](Material& m) { m.specular = Color(1.0f); }},
      {"shininess", [](Material& m) { m.shininess = 10.0; }},
      {"phong", [](Material& m) { m.phong = Color(1.0f); }},
      {"phongSize", [](Material& m) { m.phongSize = 80.0; }},
      {"brilliance", [](Material& m) { m.brilliance = 2.0; }},
      {"metallic", [](Material& m) { m.metallic = true; }},
      {"metallicAmount", [](Material& m) { m.metallicAmount = 0.5; }},
      {"metallicColor", [](Material& m) { m.metallicColor = Color(1.0f); }},
      {"reflectMetallic", [](Material& m) { m.reflectMetallic = 1.0; }},
      {"innerAmbient", [](Material& m) { m.innerAmbient = true; }},
      {"nestedExitFresnel", [](Material& m) { m.nestedExitFresnel = false; }},
      {"reflective", [](Material& m) { m.reflective = Color(0.5f); }},
      {"transmissive", [](Material& m) { m.transmissive = Color(0.5f); }},
      {"ior", [](Material& m) { m.ior = 1.5; }},
      {"fresnel", [](Material& m) { m.fresnel = true; }},
      {"reflectiveMin", [](Material& m) { m.reflectiveMin = Color(0.1f); }},
      {"reflectFalloff", [](Material& m) { m.reflectFalloff = 2.0; }},
      {"reflectExponent", [](Material& m) { m.reflectExponent = 2.0; }},
      {"fresnelTransmission", [](Material& m) { m.fresnelTransmission = false; }},
      {"conserveEnergy", [](Material& m) { m.conserveEnergy = true; }},
      {"absorption", [](Material& m) { m.absorption = Color(0.5f); }},
      {"fadeDistance", [](Material& m) { m.fadeDistance = 2.0; }},
      {"fadePower", [](Material& m) { m.fadePower = 1.0; }},
      {"fadeColor", [](Material& m) { m.fadeColor = Color(0.5f); }},
      {"fadeOnExit", [](Material& m) { m.fadeOnExit = true; }},
      {"fullTir", [](Material& m) { m.fullTir = true; }},
      {"hollow", [](Material& m) { m.hollow = true; }},
      {"irid", [](Material& m) { m.irid = 0.3; }},
      {"iridThickness", [](Material& m) { m.iridThickness = 0.3; }},
      {"iridTurbulence", [](Material& m) { m.iridTurbulence = 0.3; }},
      {"id", [](Material& m) { m.id = "named"; }},
  };
  std::vector<Material> materials{Material::defaultMaterial()};
  MaterialSharing sharing;
  const uint32_t first = sharing.add(materials, plain());
  Material again = plain();
  again.loc = SourceLoc{"elsewhere.pov", 7, 3};  // where it was written is not a term
  CHECK(sharing.add(materials, again) == first);
  for (const auto& [name, change] : changes) {
    INFO(name);
    Material m = plain();
    change(m);
    CHECK(!samePlainMaterial(m, plain()));
    const uint32_t index = sharing.add(materials, m);
    CHECK(index != first);
    CHECK(sharing.add(materials, m) == index);  // the changed one written twice: one
  }
  CHECK(materials.size() == 2 + changes.size());
}

TEST_CASE("material sharing: materials with a texture are never shared", "[scenegraph][material]") {
  Material m = plain();
  m.texture = CheckerTexture{};
  CHECK(!plainMaterial(m));
  CHECK(!samePlainMaterial(m, m));
  std::vector<Material> materials;
  MaterialSharing sharing;
  CHECK(sharing.add(materials, m) != sharing.add(materials, m));
  Material layered = plain();
  layered.layers.push_back(plain());
  CHECK(!plainMaterial(layered));
  Material bent = plain();
  bent.normal = NormalSpec{};
  CHECK(!plainMaterial(bent));
}
