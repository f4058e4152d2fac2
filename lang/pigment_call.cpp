#include "pigment_call.h"

#include "scenegraph/pigment_function.h"

#include "render/patterns/pattern_value.h"
#include "render/texture.h"

#include <algorithm>
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
  // A pattern's own value, in double precision (an isosurface of f_noise3d made of the
  // single-precision colour is bumpy at 1e-8, enough for its own shadow rays to find it),
  // held to [0, 1] as the grey map of the value does.
  if (f.component == PigmentComponent::value)
    if (const auto* t = std::get_if<PatternTexture>(&f.pigment); t && t->pigments.empty())
      return std::clamp(patternValue(t->pattern, Vec3(x, y, z)), 0.0, 1.0);
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
