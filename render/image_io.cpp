#include "image_io.h"

#include "primitives/system_memory.h"
#include "scenegraph/render_limits.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <fmt/core.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

// Clang says __has_feature(address_sanitizer); GCC defines __SANITIZE_ADDRESS__.
#if defined(__SANITIZE_ADDRESS__)
#define LUCENT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LUCENT_ASAN 1
#endif
#endif
#if defined(LUCENT_ASAN)
#include <sanitizer/lsan_interface.h>
#endif

namespace fs = std::filesystem;

namespace lucent {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// OpenImageIO's format name for each of ours.
const char* oiioFormatName(ImageFormat f) {
  switch (f) {
    case ImageFormat::Png: return "png";
    case ImageFormat::Jpeg: return "jpeg";
    case ImageFormat::Ppm: return "pnm";
    case ImageFormat::Tiff: return "tiff";
    case ImageFormat::Exr: return "openexr";
    case ImageFormat::Hdr: return "hdr";
  }
  return "";
}

// The folder a path's file lives in ("." for a bare file name).
fs::path folderOf(const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// Deletes the temporary file unless the write succeeded.
struct TempFile {
  fs::path path;
  bool keep = false;
  ~TempFile() {
    if (keep) return;
    std::error_code ec;
    fs::remove(path, ec);
  }
};

// The pixels in the file's storage type: sRGB-encoded integers or linear floats.
void encodePixels(const Image& image, ImageFormat format, OIIO::ImageSpec& spec,
                  std::vector<uint8_t>& bytes, std::vector<uint16_t>& words,
                  std::vector<float>& floats, const void*& data) {
  const size_t n = image.pixels.size() * 3;
  switch (format) {
    case ImageFormat::Png:
    case ImageFormat::Jpeg:
    case ImageFormat::Ppm: {
      spec = OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
      spec.attribute("oiio:ColorSpace", "sRGB");
      bytes.resize(n);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) bytes[3 * i + c] = static_cast<uint8_t>(srgbByte(image.pixels[i][c]));
      data = bytes.data();
      if (format == ImageFormat::Jpeg) spec.attribute("Compression", "jpeg:95");
      if (format == ImageFormat::Ppm) spec.attribute("pnm:binary", 1);
      return;
    }
    case ImageFormat::Tiff: {
      spec = OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::UINT16);
      spec.attribute("oiio:ColorSpace", "sRGB");
      spec.attribute("compression", "zip");
      words.resize(n);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
          words[3 * i + c] = static_cast<uint16_t>(
              std::floor(srgbEncode(image.pixels[i][c]) * 65535.0f + 0.5f));
      data = words.data();
      return;
    }
    case ImageFormat::Exr:
    case ImageFormat::Hdr: {
      spec = OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
      spec.attribute("oiio:ColorSpace", "Linear");
      if (format == ImageFormat::Exr) spec.attribute("compression", "zip");
      floats.resize(n);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
          float v = image.pixels[i][c];
          // RGBE shares one exponent and has no sign: negatives (and NaN) become 0.
          if (format == ImageFormat::Hdr && !(v > 0.0f)) v = 0.0f;
          floats[3 * i + c] = v;
        }
      data = floats.data();
      return;
    }
  }
}

// Flushes the file's data to the device, so a crash after the rename cannot leave an
// empty file under the final name.
void syncFile(const fs::path& path) {
  int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0 || ::fsync(fd) != 0) {
    std::string reason = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw ImageIOError(fmt::format("cannot flush '{}': {}", path.string(), reason));
  }
  ::close(fd);
}

}  // namespace

std::optional<ImageFormat> imageFormatForPath(const std::string& path) {
  std::string ext = lowerExtension(path);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
  if (ext == ".ppm") return ImageFormat::Ppm;
  if (ext == ".tif" || ext == ".tiff") return ImageFormat::Tiff;
  if (ext == ".exr") return ImageFormat::Exr;
  if (ext == ".hdr") return ImageFormat::Hdr;
  return std::nullopt;
}

const char* supportedImageExtensions() { return "png, exr, tif, jpg, hdr, ppm"; }

void checkImageOutputPath(const std::string& path) {
  if (!imageFormatForPath(path)) {
    std::string ext = fs::path(path).extension().string();
    throw ImageIOError(fmt::format(
        "cannot write '{}': {} (use one of {})", path,
        ext.empty() ? std::string("no file extension to choose the format by")
                    : "unknown image format '" + ext + "'",
        supportedImageExtensions()));
  }
  std::error_code ec;
  fs::path folder = folderOf(path);
  if (!fs::is_directory(folder, ec))
    throw ImageIOError(fmt::format("cannot write '{}': folder '{}' {}", path, folder.string(),
                                   fs::exists(folder, ec) ? "is not a folder" : "does not exist"));
  fs::file_status st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw ImageIOError(
        fmt::format("cannot write '{}': it exists and is not a regular file", path));
}

void writeImageFile(const Image& image, const std::string& path) {
  checkImageOutputPath(path);
  const ImageFormat format = *imageFormatForPath(path);
  fs::path target(path);

  // Hidden, in the same folder (so the rename stays on one file system), keeping the
  // extension, unique per process.
  TempFile temp;
  temp.path = folderOf(path) / fmt::format(".{}.lucent-{}{}", target.stem().string(),
                                           static_cast<long>(::getpid()),
                                           target.extension().string());

  OIIO::ImageSpec spec;
  std::vector<uint8_t> bytes;
  std::vector<uint16_t> words;
  std::vector<float> floats;
  const void* data = nullptr;
  encodePixels(image, format, spec, bytes, words, floats, data);

  auto out = OIIO::ImageOutput::create(oiioFormatName(format));
  if (!out)
    throw ImageIOError(fmt::format("cannot write '{}': {}", path, OIIO::geterror()));
  auto fail = [&](const std::string& what) {
    std::string reason = out->geterror();
    if (reason.empty()) reason = std::strerror(errno);
    throw ImageIOError(fmt::format("cannot write '{}': {}: {}", path, what, reason));
  };
  errno = 0;
  if (!out->open(temp.path.string(), spec)) fail("cannot create a temporary file there");
  if (!out->write_image(spec.format, data)) fail("writing failed");
  if (!out->close()) fail("writing failed");
  syncFile(temp.path);

  // Some writers do not report every failed write (a full disk, a file size limit):
  // reading the whole file back is the only proof that it is complete.
  bool complete = false;
  try {
#if defined(LUCENT_ASAN)
    // OpenImageIO 2.4's PNG reader leaks one string on a truncated file: its read callback
    // builds the error message, then libpng longjmps past the string's destructor
    // (PNGInput::PngReadCallback). A truncated file is exactly what this check looks for,
    // so LeakSanitizer ignores what is allocated during it; all else stays checked.
    __lsan::ScopedDisabler ignoreLibraryLeak;
#endif
    Image check = readImageFile(temp.path.string(), PixelDecoding::AsStored);
    complete = check.width == image.width && check.height == image.height;
  } catch (const ImageIOError&) {
  }
  if (!complete)
    throw ImageIOError(fmt::format(
        "cannot write '{}': the file written cannot be read back complete (is the disk full, "
        "or a file size limit reached?)", path));

  std::error_code ec;
  fs::rename(temp.path, target, ec);
  if (ec)
    throw ImageIOError(fmt::format("cannot write '{}': renaming the temporary file failed: {}",
                                   path, ec.message()));
  temp.keep = true;
}

Image readImageFile(const std::string& path, PixelDecoding decoding) {
  // ImageInput, not ImageBuf: an ImageBuf read by name goes through OpenImageIO's shared
  // image cache, which would return stale pixels for a file rewritten under the same name.
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw ImageIOError(fmt::format("cannot read '{}': {}", path, OIIO::geterror()));
  const OIIO::ImageSpec spec = in->spec();
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0)
    throw ImageIOError(fmt::format("cannot read '{}': the image has no pixels", path));
  // A small compressed file can claim an enormous image (a "decompression bomb"): refuse
  // it from its header, before any pixel is allocated.
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide || channels > 64)
    throw ImageIOError(fmt::format("cannot read '{}': a {}x{} image with {} channels is beyond the "
                                   "limit of {} pixels a side", path, spec.width, spec.height,
                                   channels, kMaxImageSide));
  // Float pixels as read, a decoded copy, and the linear RGB image kept.
  const std::uintmax_t need = std::uintmax_t(spec.width) * std::uintmax_t(spec.height) *
                              (2 * sizeof(float) * std::uintmax_t(channels) + sizeof(Color));
  if (auto available = availableMemoryBytes(); available && need > *available)
    throw ImageIOError(fmt::format("cannot read '{}': the {}x{} image needs about {} of memory, more "
                                   "than the {} available", path, spec.width, spec.height,
                                   formatBytes(need), formatBytes(*available)));
  std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()))
    throw ImageIOError(fmt::format("cannot read '{}': {}", path, in->geterror()));
  in->close();

  OIIO::ImageSpec floatSpec(spec.width, spec.height, channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf pixels(floatSpec, data.data());  // wraps `data`, no copy
  OIIO::ImageBuf decoded;
  const OIIO::ImageBuf* src = &pixels;
  const bool integer = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                       spec.format.basetype == OIIO::TypeDesc::UINT16;
  if (decoding == PixelDecoding::Linear && integer) {
    std::string space = spec.get_string_attribute("oiio:ColorSpace");
    if (space.empty() || OIIO::Strutil::iequals(space, "sRGB")) {
      decoded = OIIO::ImageBufAlgo::colorconvert(pixels, "sRGB", "linear", /*unpremult=*/false);
      if (decoded.has_error())
        throw ImageIOError(fmt::format("cannot decode '{}': {}", path, decoded.geterror()));
      src = &decoded;
    }
  }
  Image image(spec.width, spec.height);
  std::vector<float> px(std::max(channels, 3));
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      src->getpixel(x, y, px.data(), channels);
      image.at(x, y) = channels < 3 ? Color(px[0]) : Color(px[0], px[1], px[2]);
    }
  }
  return image;
}

}  // namespace lucent
