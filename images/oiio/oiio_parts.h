// The plugin's pieces, each in its own file; oiio_plugin.cpp puts them behind ImagePlugin.
#pragma once

#include "images/image_plugin.h"

namespace lucent::oiio {

// oiio_files.cpp
WriteFailure writeFile(const std::string& path, const ImageToWrite& image);
std::unique_ptr<ImageReader> openFile(const std::string& path, std::string& error);
std::string srgbToLinear(float* pixels, int width, int height, int channels);

// oiio_texture.cpp
std::unique_ptr<TextureSampler> textureSampler(const float* rgb, int width, int height);

// oiio_compare.cpp
CompareStats compare(const float* a, const float* b, int width, int height, float threshold);
std::vector<float> heatMap(const float* a, const float* b, int width, int height, float fullScale,
                           std::string& error);

}  // namespace lucent::oiio
