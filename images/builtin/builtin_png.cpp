// PNG through libpng, tagged as OpenImageIO 2.4's PNG writer tags it, so a file written
// here and one written by the plugin decode to the same pixels and metadata:
//   "sRGB"    sRGB chunk (absolute colorimetric intent) with its gAMA 1/2.2 and cHRM
//   "Linear"  gAMA 1.0
// and, for both, an oFFs chunk of (0, 0) pixels and the tEXt "oiio:ColorSpace" naming the
// colour space, which OpenImageIO reads back as that attribute.
#include "builtin_parts.h"
#include "png_errors.h"

#include <png.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace lucent::builtin {

namespace {

int colorTypeFor(int channels) { return channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB; }

int bitDepthFor(const ImageToWrite& image) { return image.type == StoredType::UInt16 ? 16 : 8; }

size_t rowBytes(const ImageToWrite& image) {
  return static_cast<size_t>(image.width) * image.channels * (bitDepthFor(image) / 8);
}

// PNG stores 16-bit samples big-endian; our words are in the machine's order.
constexpr bool kLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

bool encode(FILE* file, const ImageToWrite& image, ErrorSink& sink) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, onPngError, ignorePngWarning);
  if (!png) {
    std::snprintf(sink.message, sizeof sink.message, "libpng cannot start (out of memory)");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(sink.message, sizeof sink.message, "libpng cannot start (out of memory)");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), bitDepthFor(image),
               colorTypeFor(image.channels), PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (image.colorSpace == "sRGB") png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
  else png_set_gAMA(png, info, 1.0);
  png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
  // zlib level 3 instead of the default 6: half the deflate time of a typical render, files
  // within a few per cent (docs/performance-history.md, "Figures behind comments in the code").
  png_set_compression_level(png, 3);
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = const_cast<char*>("oiio:ColorSpace");
  text.text = const_cast<char*>(image.colorSpace.c_str());
  png_set_text(png, info, &text, 1);
  png_write_info(png, info);
  if (image.type == StoredType::UInt16 && kLittleEndian) png_set_swap(png);

  const size_t stride = rowBytes(image);
  const auto* pixels = static_cast<const png_byte*>(image.pixels);
  for (int y = 0; y < image.height; ++y) png_write_row(png, pixels + stride * y);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// Decodes every row into `row` (capacity bytes), then the chunks up to IEND.
bool decode(FILE* file, const ImageToWrite& image, png_byte* row, size_t capacity) {
  ErrorSink sink;
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &sink, onPngError, ignorePngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  const bool expected = png_get_image_width(png, info) == static_cast<png_uint_32>(image.width) &&
                        png_get_image_height(png, info) == static_cast<png_uint_32>(image.height) &&
                        png_get_channels(png, info) == image.channels &&
                        png_get_bit_depth(png, info) == bitDepthFor(image) &&
                        png_get_rowbytes(png, info) <= capacity;
  if (expected) {
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    for (int pass = 0; pass < passes; ++pass)
      for (int y = 0; y < image.height; ++y) png_read_row(png, row, nullptr);
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return expected;
}

}  // namespace

WriteFailure writePng(const std::string& path, const ImageToWrite& image) {
  errno = 0;
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return {WriteFailure::Create, std::strerror(errno)};
  ErrorSink sink{};
  errno = 0;
  bool written = encode(file, image, sink);
  const int cause = errno;
  std::string reason = sink.message;
  // libpng says only "Write Error"; the failed fwrite left the cause (a full disk, a file
  // size limit) in errno.
  if (!written && cause != 0) reason += std::string(" (") + std::strerror(cause) + ")";
  if (std::fclose(file) != 0 && written) {
    written = false;
    reason = std::strerror(errno);
  }
  if (!written) return {WriteFailure::Write, reason};
  return {};
}

bool pngReadsBackComplete(const std::string& path, const ImageToWrite& image) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  // Room for a row of the widest pixel libpng decodes (4 channels of 16 bits), whatever
  // the file claims.
  std::vector<png_byte> row(static_cast<size_t>(image.width) * 4 * 2);
  const bool complete = decode(file, image, row.data(), row.size());
  std::fclose(file);
  return complete;
}

}  // namespace lucent::builtin
