#include "height_map_function.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent {

uint16_t heightOfFunctionValue(double v) {
  // Measured on POV-Ray 3.7.0.10 (trace() of fields of constant functions): the value, in
  // single precision, times 65535 in single precision, truncated towards zero and kept to
  // its low 16 bits, so -0.1 stands at 58983 and 1.2 at 13106 (no clamp). A product beyond
  // the 32-bit integers (or a NaN) converts, on x86, to 0x80000000, whose low bits are 0.
  const float scaled = static_cast<float>(v) * 65535.0f;
  if (!(std::abs(scaled) < 2147483648.0f)) return 0;
  const auto stored = static_cast<uint16_t>(static_cast<uint32_t>(static_cast<int32_t>(scaled)));
  // Read back as a grey level times 65535, in single precision, truncated (exact for every
  // 16-bit value, kept for what it is).
  return static_cast<uint16_t>(static_cast<float>(stored) / 65535.0f * 65535.0f);
}

std::shared_ptr<const HeightMap> sampleHeightMap(const ScalarField& f, int width, int depth) {
  if (width < 2 || depth < 2) throw std::invalid_argument("sampleHeightMap: fewer than 2 points");
  auto m = std::make_shared<HeightMap>();
  m->width = width;
  m->depth = depth;
  m->values.resize(static_cast<size_t>(width) * static_cast<size_t>(depth));
  tbb::parallel_for(0, depth, [&](int k) {
    const double y = static_cast<double>(depth - 1 - k) / (depth - 1);
    for (int i = 0; i < width; ++i) {
      const double x = static_cast<double>(i) / (width - 1);
      m->values[static_cast<size_t>(k) * width + i] =
          heightOfFunctionValue(f.value(Vec3(x, y, 0.0)));
    }
  });
  return m;
}

}  // namespace lucent
