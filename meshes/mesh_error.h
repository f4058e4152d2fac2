// A mesh that cannot be read or repaired into usable triangles.
#pragma once

#include <stdexcept>

namespace lucent {

// The message names the reason; the caller adds the file name and scene location.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace lucent
