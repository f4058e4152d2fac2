// Binary PPM (P6) in plain code: the header "P6\nW H\n255\n" and the RGB bytes, row 0
// first; byte for byte what OpenImageIO's PNM writer writes for pnm:binary.
#include "builtin_parts.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace lucent::builtin {

namespace {

size_t pixelBytes(const ImageToWrite& image) {
  return static_cast<size_t>(image.width) * image.height * 3;
}

}  // namespace

WriteFailure writePpm(const std::string& path, const ImageToWrite& image) {
  errno = 0;
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return {WriteFailure::Create, std::strerror(errno)};
  const size_t n = pixelBytes(image);
  errno = 0;
  bool written = std::fprintf(file, "P6\n%d %d\n255\n", image.width, image.height) > 0 &&
                 std::fwrite(image.pixels, 1, n, file) == n;
  std::string reason = written ? "" : std::strerror(errno);
  if (std::fclose(file) != 0 && written) {
    written = false;
    reason = std::strerror(errno);
  }
  if (!written) return {WriteFailure::Write, reason};
  return {};
}

bool ppmReadsBackComplete(const std::string& path, const ImageToWrite& image) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  int width = 0, height = 0, maxValue = 0;
  // The header as writePpm writes it, then every pixel byte and nothing after them.
  bool complete = std::fscanf(file, "P6 %d %d %d", &width, &height, &maxValue) == 3 &&
                  std::fgetc(file) == '\n' && width == image.width && height == image.height &&
                  maxValue == 255;
  if (complete) {
    std::vector<char> chunk(1 << 16);
    size_t total = 0;
    for (size_t got; (got = std::fread(chunk.data(), 1, chunk.size(), file)) > 0;) total += got;
    complete = total == pixelBytes(image) && !std::ferror(file);
  }
  std::fclose(file);
  return complete;
}

}  // namespace lucent::builtin
