#include "camera_inside_warning.h"

#include "scenegraph/camera_inside.h"

#include <fmt/core.h>

namespace lucent {

namespace {

// Shortest exact form, and no "-0".
std::string number(double v) { return fmt::format("{}", v + 0.0); }

std::string cameraName(const Camera& camera) {
  std::string where = camera.loc.str();
  return camera.name.empty() ? "the camera at " + where
                             : fmt::format("camera \"{}\" ({})", camera.name, where);
}

}  // namespace

void warnCamerasInsideOpaqueSolids(const Scene& scene, Diagnostics& diags) {
  for (const CameraInSolid& c : camerasInsideOpaqueSolids(scene)) {
    const Node& solid = *c.solid;
    std::string fix = "move the camera out of it";
    if (solid.shape)
      if (const auto* plane = std::get_if<PlaneSpec>(&*solid.shape)) {
        const Vec3& n = plane->normal;
        // Negating both keeps the surface and swaps the half-spaces: the camera's side
        // becomes the outside (as POV-Ray's plane { -n, -d } for plane { n, d }).
        fix = fmt::format(
            "to put the camera outside and keep the surface, negate the normal and "
            "the offset: normal=\"{} {} {}\" offset=\"{}\"",
            number(-n.x), number(-n.y), number(-n.z), number(-plane->offset));
      }
    diags.warning(solid.loc,
                  fmt::format("{} is inside this opaque <{}>: its rays start inside it, so the "
                              "surfaces they meet from inside lose their ambient term (inside an "
                              "object it is multiplied by the transmissive colour, 0 here); {}",
                              cameraName(*c.camera), solid.element, fix));
  }
}

}  // namespace lucent
