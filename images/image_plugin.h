// OpenImageIO behind a plugin that is loaded on first use, so that a run which reads or
// writes no image never pays for it.
//
// Why: Debian's OpenImageIO 2.4 pulls 260 shared libraries into a process (OpenCV, FFmpeg,
// GDAL, OpenVDB, DCMTK...): about 0.4 s of CPU time and 130 MB of resident memory before
// the first line of main. `lucent --help`, `check`, a scene with an error or an export
// need none of it, and a render loads it only once its scene is freed, so the two are
// never in memory together. A render to PNG or PPM with PNG or JPEG textures, the common
// case, does not load it at all: those files are written and read by the built-in part
// (builtin/builtin_images.h), and textures are decoded and sampled by Lucent's own code
// (srgb_decoding.h, periodic_bilinear.h). Every other image is read, written and compared
// by OpenImageIO: the plugin (images/oiio/, the file lucent-oiio.so) is the only code
// that includes its headers.
//
// The interface is a C++ abstract class: the plugin is built by the same compiler from the
// same tree, so C++ types and exceptions cross the boundary safely. Pixels cross it as
// plain float or integer arrays, row-major, row 0 at the top.
#pragma once

#include <cctype>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucent {

// The plugin cannot be found or loaded; the message says which files were tried.
struct ImagePluginError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a file's header says, before any pixel is read.
struct ImageHeader {
  int width = 0;
  int height = 0;
  int channels = 0;
  bool eightBit = false;    // stored as 8-bit integers
  bool sixteenBit = false;  // stored as 16-bit integers
  bool floating = false;    // stored as floating point
  int alphaChannel = -1;    // the alpha channel's index, or -1
  std::string colorSpace;   // OpenImageIO's "oiio:ColorSpace" (empty if the file says none)

  // Does the file say its values are gamma-encoded as sRGB's are (in any letter case)?
  // OpenImageIO labels every PPM "Rec709": Netpbm's samples are gamma-encoded, and Lucent
  // writes its PPMs sRGB-encoded, so they are decoded as sRGB, as 8-bit files that say
  // nothing are.
  bool saysSrgb() const { return colorSpaceIs("srgb") || colorSpaceIs("rec709"); }

 private:
  bool colorSpaceIs(const char* lower) const {
    size_t i = 0;
    for (; lower[i]; ++i)
      if (i >= colorSpace.size() ||
          std::tolower(static_cast<unsigned char>(colorSpace[i])) != lower[i])
        return false;
    return i == colorSpace.size();
  }
};

// An image file opened for reading.
class ImageReader {
 public:
  virtual ~ImageReader() = default;
  virtual const ImageHeader& header() const = 0;
  // All channels of all pixels as floats: integer code values scaled to [0, 1], no colour
  // conversion. `out` holds width * height * channels floats. Returns "" or the reason.
  virtual std::string readPixels(float* out) = 0;
};

// How a file stores its pixels.
enum class StoredType { UInt8, UInt16, Float };

// Pixels to write, already encoded (sRGB bytes, 16-bit words or linear floats), with the
// metadata that goes into the file.
struct ImageToWrite {
  std::string format;  // OpenImageIO's format name: "png", "openexr", "tiff"...
  int width = 0;
  int height = 0;
  int channels = 3;
  StoredType type = StoredType::UInt8;
  const void* pixels = nullptr;
  std::string colorSpace;   // "sRGB" or "Linear"
  std::string compression;  // "" for the format's default
  bool pnmBinary = false;   // PPM: binary (P6), not text
};

// Bilinear lookup of a float RGB image with periodic wrapping (OpenImageIO's
// interppixel_NDC); the sampler only views the pixels, which must outlive it. The
// reference that Lucent's own lookup (periodic_bilinear.h) is tested against.
class TextureSampler {
 public:
  virtual ~TextureSampler() = default;
  // (s, t) in [0,1]^2 spans the image, t = 0 at row 0; writes three floats to rgb.
  virtual void lookup(float s, float t, float* rgb) const = 0;
};

// The differences of two images of equal size (OpenImageIO's ImageBufAlgo::compare).
struct CompareStats {
  double rmsError = 0.0;  // over all pixels and channels
  double maxError = 0.0;  // largest channel difference
  int maxX = 0, maxY = 0;
  long pixelsOver = 0;  // pixels with some channel off by more than the threshold
};

// Why a file was not written: at which step, and OpenImageIO's reason (or the system's).
struct WriteFailure {
  enum Step { None, Create, Write } step = None;
  std::string reason;
  explicit operator bool() const { return step != None; }
};

class ImagePlugin {
 public:
  // Writes the file (the format is `image.format`, whatever the path's extension).
  virtual WriteFailure writeFile(const std::string& path, const ImageToWrite& image) const = 0;
  // Opens a file and reads its header; null with `error` set if that fails. The reader
  // goes straight to the file (never through a cache, which could return stale pixels
  // for a file rewritten under the same name).
  virtual std::unique_ptr<ImageReader> openFile(const std::string& path,
                                                std::string& error) const = 0;
  // Decodes sRGB-encoded values in place to linear (OpenImageIO's colour conversion, which
  // approximates the power): the reference Lucent's exact decoding (srgb_decoding.h) is
  // tested against. Returns "" or the reason.
  virtual std::string srgbToLinear(float* pixels, int width, int height, int channels) const = 0;
  virtual std::unique_ptr<TextureSampler> textureSampler(const float* rgb, int width,
                                                         int height) const = 0;
  // a and b: width * height RGB floats each.
  virtual CompareStats compare(const float* a, const float* b, int width, int height,
                               float threshold) const = 0;
  // The largest channel difference per pixel through the "inferno" colour map, brightest
  // at `fullScale`: width * height RGB floats, or empty with `error` set.
  virtual std::vector<float> heatMap(const float* a, const float* b, int width, int height,
                                     float fullScale, std::string& error) const = 0;

 protected:
  ~ImagePlugin() = default;
};

// The plugin, loaded on the first call. Thread-safe. Throws ImagePluginError if it cannot
// be loaded.
const ImagePlugin& imagePlugin();

// The plugin's version of the interface; a plugin built from another tree is refused.
constexpr int kImagePluginVersion = 1;

}  // namespace lucent

// The plugin's one exported symbol: returns its ImagePlugin and the version it implements.
extern "C" {
using LucentImagePluginEntry = const lucent::ImagePlugin* (*)(int* version);
}
#define LUCENT_IMAGE_PLUGIN_ENTRY "lucent_image_plugin"
