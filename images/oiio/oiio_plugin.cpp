// The plugin's entry point: the ImagePlugin interface over the OpenImageIO pieces.
#include "oiio_parts.h"

namespace lucent::oiio {

namespace {

class OiioPlugin final : public ImagePlugin {
 public:
  WriteFailure writeFile(const std::string& path, const ImageToWrite& image) const override {
    return oiio::writeFile(path, image);
  }
  std::unique_ptr<ImageReader> openFile(const std::string& path,
                                        std::string& error) const override {
    return oiio::openFile(path, error);
  }
  std::string srgbToLinear(float* pixels, int width, int height, int channels) const override {
    return oiio::srgbToLinear(pixels, width, height, channels);
  }
  std::unique_ptr<TextureSampler> textureSampler(const float* rgb, int width,
                                                 int height) const override {
    return oiio::textureSampler(rgb, width, height);
  }
  CompareStats compare(const float* a, const float* b, int width, int height,
                       float threshold) const override {
    return oiio::compare(a, b, width, height, threshold);
  }
  std::vector<float> heatMap(const float* a, const float* b, int width, int height, float fullScale,
                             std::string& error) const override {
    return oiio::heatMap(a, b, width, height, fullScale, error);
  }
};

}  // namespace

}  // namespace lucent::oiio

extern "C" __attribute__((visibility("default"))) const lucent::ImagePlugin* lucent_image_plugin(
    int* version) {
  static const lucent::oiio::OiioPlugin plugin;
  *version = lucent::kImagePluginVersion;
  return &plugin;
}
