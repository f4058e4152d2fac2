// After a render: the isosurfaces whose function changed faster along the rays than their
// max-gradient allows (POV-Ray says the same after its render), since the root search may
// then have skipped parts of the surface.
#pragma once

#include "scene.h"

#include <string>
#include <vector>

namespace lucent {

// "file:line:col: warning: <isosurface> ...", one for each such isosurface, in tree order.
std::vector<std::string> gradientWarnings(const Scene& scene);

}  // namespace lucent
