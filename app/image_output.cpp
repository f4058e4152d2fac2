#include "image_output.h"

#include "images/address_sanitizer.h"
#include "images/builtin/builtin_images.h"
#include "images/image_plugin.h"

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
    case ImageFormat::Png:
      return "png";
    case ImageFormat::Jpeg:
      return "jpeg";
    case ImageFormat::Ppm:
      return "pnm";
    case ImageFormat::Tiff:
      return "tiff";
    case ImageFormat::Exr:
      return "openexr";
    case ImageFormat::Hdr:
      return "hdr";
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
ImageToWrite encodePixels(const Image& image, ImageFormat format, std::vector<uint8_t>& bytes,
                          std::vector<uint16_t>& words, std::vector<float>& floats) {
  ImageToWrite out;
  out.format = oiioFormatName(format);
  out.width = image.width;
  out.height = image.height;
  out.channels = 3;
  const size_t n = image.pixels.size() * 3;
  switch (format) {
    case ImageFormat::Png:
    case ImageFormat::Jpeg:
    case ImageFormat::Ppm: {
      out.type = StoredType::UInt8;
      out.colorSpace = "sRGB";
      bytes.resize(n);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
          bytes[3 * i + c] = static_cast<uint8_t>(srgbByte(image.pixels[i][c]));
      out.pixels = bytes.data();
      if (format == ImageFormat::Jpeg) out.compression = "jpeg:95";
      if (format == ImageFormat::Ppm) out.pnmBinary = true;
      return out;
    }
    case ImageFormat::Tiff: {
      out.type = StoredType::UInt16;
      out.colorSpace = "sRGB";
      out.compression = "zip";
      words.resize(n);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
          words[3 * i + c] =
              static_cast<uint16_t>(std::floor(srgbEncode(image.pixels[i][c]) * 65535.0f + 0.5f));
      out.pixels = words.data();
      return out;
    }
    case ImageFormat::Exr:
    case ImageFormat::Hdr: {
      out.type = StoredType::Float;
      out.colorSpace = "Linear";
      if (format == ImageFormat::Exr) out.compression = "zip";
      floats.resize(n);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
          float v = image.pixels[i][c];
          // RGBE shares one exponent and has no sign: negatives (and NaN) become 0.
          if (format == ImageFormat::Hdr && !(v > 0.0f)) v = 0.0f;
          floats[3 * i + c] = v;
        }
      out.pixels = floats.data();
      return out;
    }
  }
  return out;
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

// Does the file open as an image of this size whose every pixel can be read? The pixels
// are read into one buffer and dropped (no decoded copy).
bool readsBackComplete(const std::string& path, int width, int height) {
  std::string error;
  std::unique_ptr<ImageReader> in = imagePlugin().openFile(path, error);
  if (!in) return false;
  const ImageHeader& h = in->header();
  if (h.width != width || h.height != height || h.channels < 1 || h.channels > 4) return false;
  std::vector<float> pixels(static_cast<size_t>(width) * height * h.channels);
  return in->readPixels(pixels.data()).empty();
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
    throw ImageIOError(fmt::format("cannot write '{}': {} (use one of {})", path,
                                   ext.empty()
                                       ? std::string("no file extension to choose the format by")
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
    throw ImageIOError(fmt::format("cannot write '{}': it exists and is not a regular file", path));
}

void writeImageFile(const Image& image, const std::string& path, ImageWriter writer) {
  checkImageOutputPath(path);
  const ImageFormat format = *imageFormatForPath(path);
  fs::path target(path);

  // Hidden, in the same folder (so the rename stays on one file system), keeping the
  // extension, unique per process.
  TempFile temp;
  temp.path =
      folderOf(path) / fmt::format(".{}.lucent-{}{}", target.stem().string(),
                                   static_cast<long>(::getpid()), target.extension().string());

  std::vector<uint8_t> bytes;
  std::vector<uint16_t> words;
  std::vector<float> floats;
  ImageToWrite pixels = encodePixels(image, format, bytes, words, floats);
  // PNG and PPM, the common outputs, need not load OpenImageIO's 260 libraries.
  const bool builtin = writer == ImageWriter::Automatic && builtinWrites(pixels);
  if (WriteFailure failed = builtin ? builtinWriteFile(temp.path.string(), pixels)
                                    : imagePlugin().writeFile(temp.path.string(), pixels))
    throw ImageIOError(fmt::format("cannot write '{}': {}: {}", path,
                                   failed.step == WriteFailure::Create
                                       ? "cannot create a temporary file there"
                                       : "writing failed",
                                   failed.reason));
  syncFile(temp.path);

  // Some writers do not report every failed write (a full disk, a file size limit):
  // reading the whole file back is the only proof that it is complete.
  // The built-in formats are read back by the built-in part, a row at a time.
  // Otherwise the encoded pixels are done with: freed first, as the check holds a decoded
  // copy.
  bool complete = false;
  if (builtin) {
    complete = builtinReadsBackComplete(temp.path.string(), pixels);
  } else {
    std::vector<uint8_t>().swap(bytes);
    std::vector<uint16_t>().swap(words);
    std::vector<float>().swap(floats);
#if defined(LUCENT_ASAN)
    // OpenImageIO 2.4's PNG reader leaks one string on a truncated file: its read callback
    // builds the error message, then libpng longjmps past the string's destructor
    // (PNGInput::PngReadCallback). A truncated file is exactly what this check looks for,
    // so LeakSanitizer ignores what is allocated during it; all else stays checked.
    __lsan::ScopedDisabler ignoreLibraryLeak;
#endif
    complete = readsBackComplete(temp.path.string(), image.width, image.height);
  }
  if (!complete)
    throw ImageIOError(fmt::format(
        "cannot write '{}': the file written cannot be read back complete (is the disk full, "
        "or a file size limit reached?)",
        path));

  std::error_code ec;
  fs::rename(temp.path, target, ec);
  if (ec)
    throw ImageIOError(fmt::format("cannot write '{}': renaming the temporary file failed: {}",
                                   path, ec.message()));
  temp.keep = true;
}

}  // namespace lucent
