// Texture lookups through OpenImageIO: bilinear, wrapping periodically.
#include "oiio_parts.h"

#include <OpenImageIO/imagebuf.h>

namespace lucent::oiio {

namespace {

class BufferSampler final : public TextureSampler {
 public:
  BufferSampler(const float* rgb, int width, int height) {
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    pixels_.reset(spec, const_cast<float*>(rgb));  // a view: read only, never written
  }
  void lookup(float s, float t, float* rgb) const override {
    pixels_.interppixel_NDC(s, t, rgb, OIIO::ImageBuf::WrapPeriodic);
  }

 private:
  OIIO::ImageBuf pixels_;
};

}  // namespace

std::unique_ptr<TextureSampler> textureSampler(const float* rgb, int width, int height) {
  return std::make_unique<BufferSampler>(rgb, width, height);
}

}  // namespace lucent::oiio
