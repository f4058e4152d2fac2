#include "container_fields.h"

#include <fmt/format.h>

namespace lucent {

IsosurfaceContainer readContainer(AttributeInput& in) {
  IsosurfaceContainer c;
  const bool sphere = in.choice("container", 0, kContainerKinds) == 1;
  c.kind = sphere ? IsosurfaceContainer::Sphere : IsosurfaceContainer::Box;
  for (const char* a : sphere ? std::vector<const char*>{"min", "max"}
                              : std::vector<const char*>{"center", "radius"})
    if (in.has(a))
      in.attrError(a, sphere ? "a sphere container has 'center' and 'radius'; 'min' and 'max' "
                               "belong to a box"
                             : "a box container has 'min' and 'max'; 'center' and 'radius' "
                               "belong to container=\"sphere\"");
  if (sphere) {
    c.center = in.vector("center", Vec3(0.0));
    c.radius = in.number("radius", 1.0, NumberRule::positive());
    return c;
  }
  c.min = in.vector("min", Vec3(-1.0));
  c.max = in.vector("max", Vec3(1.0));
  const Vec3 &lo = c.min, &hi = c.max;
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
    in.attrError(in.has("max") ? "max" : "min",
                 fmt::format("the container box needs min < max in x, y and z (min {} {} {}, "
                             "max {} {} {})",
                             lo.x, lo.y, lo.z, hi.x, hi.y, hi.z));
  return c;
}

std::string povContainer(const IsosurfaceContainer& c, const PovShapeOut& out) {
  if (c.kind == IsosurfaceContainer::Box)
    return fmt::format("contained_by {{ box {{ {}, {} }} }}", out.vector(c.min), out.vector(c.max));
  return fmt::format("contained_by {{ sphere {{ {}, {} }} }}", out.vector(c.center),
                     out.number(c.radius));
}

}  // namespace lucent
