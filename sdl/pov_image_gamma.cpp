#include "pov_image_gamma.h"

#include "images/builtin/builtin_images.h"

#include <algorithm>
#include <cctype>

namespace lucent::sdl {

namespace {

// The format's name as POV-Ray's keyword gives it, from a keyword or an extension.
std::string formatName(std::string format) {
  if (!format.empty() && format[0] == '.') format.erase(0, 1);
  std::transform(format.begin(), format.end(), format.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (format == "jpg") return "jpeg";
  if (format == "tif") return "tiff";
  return format;
}

}  // namespace

GammaCurve povImageMapGamma(const std::string& path, const std::string& format,
                            const std::optional<GammaCurve>& keyword,
                            const PovGlobalSettings& global, double languageVersion) {
  // The image's own gamma overrides whatever the file or the format says, float files too.
  if (keyword) return *keyword;
  const GammaCurve working = povWorkingGamma(global, languageVersion);
  const GammaCurve srgb{true, 1.0};
  const bool legacy = languageVersion < 3.7;
  // Gamma correction off (an older scene without assumed_gamma): the values as they are.
  // So are they wherever POV-Ray's reader applies no curve: the file's values taken as
  // working values, which the working curve itself decodes.
  if (legacy && !global.assumedGamma) return working;
  const std::string f = formatName(format);
  if (f == "exr" || f == "hdr") return GammaCurve{};  // linear light
  if (f == "png") {
    // An sRGB chunk, else a gAMA chunk (the encoding gamma: 0.45455 for 2.2), else none:
    // sRGB as the PNG specification recommends, or in a 3.6 scene the working gamma.
    PngPixels png;
    if (readPngHeader(path, png).empty()) {
      if (png.srgbChunk) return srgb;
      if (png.fileGamma > 0.0) return GammaCurve{false, 1.0 / png.fileGamma};
    }
    return legacy ? working : srgb;
  }
  if (f == "jpeg" || f == "tga" || f == "gif") return legacy ? working : srgb;
  return working;  // ppm, pgm, tiff, bmp: POV-Ray's readers apply no curve
}

}  // namespace lucent::sdl
