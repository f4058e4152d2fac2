#include "png_bytes.h"

#include <png.h>

#include <csetjmp>
#include <new>
#include <stdexcept>
#include <vector>

namespace lucent::preview {

namespace {

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void flush(png_structp) {}

void ignore(png_structp, png_const_charp) {}

// Writes the rows; false when libpng failed (it then long-jumps back here; nothing between
// has a destructor).
bool encode(png_structp png, png_infop info, const Image& image, std::vector<png_byte>& row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  // Sent at once to a browser on this machine: speed over size.
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Color& c = image.at(x, y);
      for (int k = 0; k < 3; ++k) row[3 * x + k] = static_cast<png_byte>(srgbByte(c[k]));
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string pngBytes(const Image& image) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, ignore);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw std::bad_alloc();
  }
  std::vector<png_byte> row(static_cast<size_t>(image.width) * 3);
  png_set_write_fn(png, &out, append, flush);
  const bool written = encode(png, info, image, row);
  png_destroy_write_struct(&png, &info);
  if (!written) throw std::runtime_error("libpng cannot encode the preview image");
  return out;
}

}  // namespace lucent::preview
