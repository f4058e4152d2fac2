// Image differences through OpenImageIO's ImageBufAlgo: the metrics and the heat map.
#include "oiio_parts.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace lucent::oiio {

namespace {

// A view of RGB floats as an OpenImageIO buffer (no copy; never written through).
OIIO::ImageBuf wrap(const float* rgb, int width, int height) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
  return OIIO::ImageBuf(spec, const_cast<float*>(rgb));
}

}  // namespace

CompareStats compare(const float* a, const float* b, int width, int height, float threshold) {
  OIIO::ImageBuf bufA = wrap(a, width, height), bufB = wrap(b, width, height);
  // failthresh = threshold: nfail counts the pixels with a channel off by more than it.
  // (r.error is set whenever some pixel fails the threshold: not a processing error.)
  OIIO::ImageBufAlgo::CompareResults r =
      OIIO::ImageBufAlgo::compare(bufA, bufB, threshold, threshold);
  CompareStats s;
  s.rmsError = r.rms_error;
  s.maxError = r.maxerror;
  s.maxX = r.maxx;
  s.maxY = r.maxy;
  s.pixelsOver = static_cast<long>(r.nfail);
  return s;
}

std::vector<float> heatMap(const float* a, const float* b, int width, int height, float fullScale,
                           std::string& error) {
  OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(wrap(a, width, height), wrap(b, width, height));
  OIIO::ImageBuf largest = OIIO::ImageBufAlgo::maxchan(diff);
  OIIO::ImageBuf scaled = OIIO::ImageBufAlgo::mul(largest, 1.0f / fullScale);
  OIIO::ImageBuf clamped = OIIO::ImageBufAlgo::clamp(scaled, 0.0f, 1.0f);
  OIIO::ImageBuf mapped = OIIO::ImageBufAlgo::color_map(clamped, 0, "inferno");
  if (mapped.has_error()) {
    error = mapped.geterror();
    return {};
  }
  std::vector<float> rgb(static_cast<size_t>(width) * height * 3);
  const OIIO::ImageSpec& spec = mapped.spec();
  mapped.get_pixels(OIIO::ROI(spec.x, spec.x + width, spec.y, spec.y + height, 0, 1, 0, 3),
                    OIIO::TypeDesc::FLOAT, rgb.data());
  return rgb;
}

}  // namespace lucent::oiio
