// Reading a PNG's stored values through libpng, for the readers that need no colour
// management (height fields): grey of 1 to 16 bits, grey with alpha, RGB and RGBA of 8 or
// 16 bits, interlaced or not. Bits below 8 are widened as libpng widens them (a 2-bit 3
// becomes 255), which is what OpenImageIO's PNG reader gives too. Palette images are left
// to the caller. libpng reports errors by longjmp, so the function that drives it holds no
// C++ object with a destructor: a first pass reads the header, the caller makes the
// buffer, and a second pass reads the values (png_errors.h).
#include "builtin_images.h"
#include "png_errors.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace lucent {

namespace {

using builtin::ErrorSink;

// libpng's own reader says only "Read Error"; this one says why.
void readData(png_structp png, png_bytep data, size_t length) {
  FILE* file = static_cast<FILE*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, file) != length)
    png_error(png,
              std::feof(file) ? "the file ends before its image does" : "the file cannot be read");
}

// The transformations both passes set: stored values, 16 bits in the machine's order; a
// palette image's indices, a byte each (not its colours), or, expanded as OpenImageIO
// expands them, a palette's colours and tRNS as an alpha channel.
void setTransforms(png_structp png, png_infop info, bool expandAsOiio) {
  if (png_get_bit_depth(png, info) == 16) png_set_swap(png);
  if (expandAsOiio) {
    png_set_expand(png);
    return;
  }
  if (png_get_color_type(png, info) == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8)
    png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE && png_get_bit_depth(png, info) < 8)
    png_set_packing(png);
}

// The palette's colours and the alphas of its tRNS chunk (the header pass: libpng keeps
// them in the info struct once png_read_info has run).
void readPalette(png_structp png, png_infop info, PngPixels& pixels) {
  pixels.transparencyChunk = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  pixels.paletteColours.clear();
  png_colorp palette = nullptr;
  int count = 0;
  if (!pixels.palette || !png_get_PLTE(png, info, &palette, &count)) return;
  png_bytep alphas = nullptr;
  int alphaCount = 0;
  if (pixels.transparencyChunk) png_get_tRNS(png, info, &alphas, &alphaCount, nullptr);
  for (int i = 0; i < count; ++i)
    pixels.paletteColours.push_back(
        {palette[i].red, palette[i].green, palette[i].blue,
         static_cast<std::uint8_t>(alphas && i < alphaCount ? alphas[i] : 255)});
}

// The text chunk OpenImageIO takes as the colour space's name (Lucent's PNGs carry one).
// The string is assigned only here, after libpng has returned: no longjmp crosses it.
void readColorSpaceText(png_structp png, png_infop info, PngPixels& pixels) {
  png_textp text = nullptr;
  const int count = png_get_text(png, info, &text, nullptr);
  pixels.colorSpaceText.clear();
  for (int i = 0; i < count; ++i)
    if (text[i].key && text[i].text && std::strcmp(text[i].key, "oiio:ColorSpace") == 0)
      pixels.colorSpaceText = text[i].text;
}

// A read struct and its info reporting to `sink`; false (nothing to free) if libpng has no
// memory for them.
bool startReading(ErrorSink& sink, png_structp& png, png_infop& info) {
  png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &sink, builtin::onPngError,
                               builtin::ignorePngWarning);
  if (!png) return false;
  info = png_create_info_struct(png);
  if (info) return true;
  png_destroy_read_struct(&png, nullptr, nullptr);
  return false;
}

// One pass over the file. Without `values`: the header's facts into `pixels`. With them:
// the values of the image `pixels` describes (rows of width x channels samples, a byte each
// or, for 16 bits, two), every row and chunk up to IEND. False with `sink` set on a
// damaged file.
bool readPass(FILE* file, PngPixels& pixels, unsigned char* values, ErrorSink& sink) {
  png_structp png = nullptr;
  png_infop info = nullptr;
  if (!startReading(sink, png, info)) return false;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, file, readData);
  png_read_info(png, info);
  if (!values) {
    pixels.width = static_cast<int>(png_get_image_width(png, info));
    pixels.height = static_cast<int>(png_get_image_height(png, info));
    pixels.palette =
        !pixels.expandAsOiio && png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE;
    pixels.storedDepth = png_get_bit_depth(png, info);
    readPalette(png, info, pixels);
    int intent = 0;
    pixels.srgbChunk = png_get_sRGB(png, info, &intent) != 0;
    double gamma = 0.0;
    pixels.fileGamma = png_get_gAMA(png, info, &gamma) ? gamma : 0.0;
    readColorSpaceText(png, info, pixels);
  }
  setTransforms(png, info, pixels.expandAsOiio);
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (!values) {
    pixels.channels = png_get_channels(png, info);
    pixels.sixteenBit = png_get_bit_depth(png, info) == 16;
  } else {
    const size_t rowBytes =
        static_cast<size_t>(pixels.width) * pixels.channels * (pixels.sixteenBit ? 2 : 1);
    if (png_get_rowbytes(png, info) != rowBytes) png_error(png, "the image changed while read");
    for (int pass = 0; pass < passes; ++pass)
      for (int y = 0; y < pixels.height; ++y)
        png_read_row(png, values + static_cast<size_t>(y) * rowBytes, nullptr);
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

bool isPngFile(const std::string& path) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  unsigned char b[8] = {};
  const size_t n = std::fread(b, 1, sizeof b, file);
  std::fclose(file);
  return n == sizeof b && png_sig_cmp(b, 0, sizeof b) == 0;
}

std::string readPngHeader(const std::string& path, PngPixels& out) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::strerror(errno);
  ErrorSink sink{};
  const bool ok = readPass(file, out, nullptr, sink);
  std::fclose(file);
  return ok ? std::string() : std::string("a damaged PNG: ") + sink.message;
}

std::string readPngValues(const std::string& path, PngPixels& pixels) {
  const size_t samples = static_cast<size_t>(pixels.width) * pixels.height * pixels.channels;
  std::vector<unsigned char> bytes(samples * (pixels.sixteenBit ? 2 : 1));
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::strerror(errno);
  ErrorSink sink{};
  const bool ok = readPass(file, pixels, bytes.data(), sink);
  std::fclose(file);
  if (!ok) return std::string("a damaged PNG: ") + sink.message;
  pixels.values.resize(samples);
  for (size_t i = 0; i < samples; ++i) {
    if (pixels.sixteenBit) {
      std::uint16_t v;
      std::memcpy(&v, &bytes[2 * i], 2);  // png_set_swap: the machine's order
      pixels.values[i] = v;
    } else {
      pixels.values[i] = bytes[i];
    }
  }
  return {};
}

}  // namespace lucent
