#include "pigment_call.h"

#include "scenegraph/pigment_function.h"

#include "render/texture.h"

#include <cmath>
#include <limits>

namespace lucent {

namespace {

double call(void* data, double x, double y, double z) {
  return pigmentFunctionValue(*static_cast<const PigmentFunction*>(data), x, y, z);
}

}  // namespace

double pigmentFunctionValue(const PigmentFunction& f, double x, double y, double z) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    return std::numeric_limits<double>::quiet_NaN();
  return pigmentComponent(pigmentAt(f.pigment, Vec3(x, y, z), Vec3(0.0)), f.component);
}

void definePigmentFunctions(mu::Parser& parser,
                            const std::vector<std::shared_ptr<const PigmentFunction>>& pigments) {
  // Never folded at compile time: an imported pigment's noise generator is settled after
  // its function is compiled (sdl's finishScene), before any render thread compiles its own.
  for (const auto& p : pigments)
    parser.DefineFunUserData(p->name, call, const_cast<PigmentFunction*>(p.get()), false);
}

}  // namespace lucent
