// JPEG files read through libjpeg-turbo as OpenImageIO 2.4's JPEG reader reads them, so a
// texture decodes to the same pixels either way (tests/images/builtin_texture_read_test.cpp):
// libjpeg's default decoding (the accurate integer DCT, smooth chroma upsampling), grey as
// one channel, YCbCr as RGB, CMYK and YCCK turned to RGB by R = C K (OpenImageIO's rule),
// every file labelled sRGB. A warning from libjpeg (data ending early, a corrupt segment)
// is an error, as OpenImageIO makes it: a damaged file is refused, not filled with grey.
// libjpeg reports errors by longjmp, so the function that drives it holds no C++ object
// with a destructor.
#include "builtin_readers.h"

#include <jpeglib.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

namespace lucent::builtin {

namespace {

struct JpegErrors {
  jpeg_error_mgr manager;  // first: libjpeg hands the callbacks a pointer to it
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onJpegError(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  (*info->err->format_message)(info, errors->message);
  std::longjmp(errors->jump, 1);
}

// Level -1 is a warning (the rest are traces, silent by default): refused as an error.
void onJpegMessage(j_common_ptr info, int level) {
  if (level < 0) onJpegError(info);
}

struct JpegFacts {
  int width = 0, height = 0;
  int components = 0;  // as decoded: 1 grey, 3 RGB, 4 CMYK
  bool cmyk = false;
};

// One pass over the file: the header's facts, and with `rows` (height rows of width x
// components bytes) the pixels. False with errors.message set on a damaged file.
bool decode(FILE* file, JpegFacts& facts, unsigned char* rows, JpegErrors& errors) {
  jpeg_decompress_struct info;
  info.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = onJpegError;
  errors.manager.emit_message = onJpegMessage;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, file);
  jpeg_read_header(&info, TRUE);
  facts.cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
  if (facts.cmyk) info.out_color_space = JCS_CMYK;
  jpeg_start_decompress(&info);
  facts.width = static_cast<int>(info.output_width);
  facts.height = static_cast<int>(info.output_height);
  facts.components = info.output_components;
  if (rows) {
    const size_t rowBytes = static_cast<size_t>(facts.width) * facts.components;
    while (info.output_scanline < info.output_height) {
      JSAMPROW row = rows + static_cast<size_t>(info.output_scanline) * rowBytes;
      jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
  }
  jpeg_destroy_decompress(&info);
  return true;
}

// decode() on the file at `path`: "" or the reason.
std::string decodeFile(const std::string& path, JpegFacts& facts, unsigned char* rows) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::strerror(errno);
  JpegErrors errors{};
  const bool ok = decode(file, facts, rows, errors);
  std::fclose(file);
  return ok ? std::string() : std::string("a damaged JPEG: ") + errors.message;
}

// OpenImageIO's conversion of a byte to float and back (convert_type).
float byteToFloat(unsigned char b) { return static_cast<float>(b) * (1.0f / 255.0f); }
unsigned char floatToByte(float f) {
  const float s = f * 255.0f + 0.5f;
  return static_cast<unsigned char>(s < 0.0f ? 0.0f : s > 255.0f ? 255.0f : s);
}

class JpegReader final : public ImageReader {
 public:
  JpegReader(std::string path, const JpegFacts& facts) : path_(std::move(path)), facts_(facts) {
    header_.width = facts.width;
    header_.height = facts.height;
    header_.channels = facts.cmyk ? 3 : facts.components;
    header_.eightBit = true;
    header_.colorSpace = "sRGB";
  }

  const ImageHeader& header() const override { return header_; }

  std::string readPixels(float* out) override {
    const size_t count = static_cast<size_t>(facts_.width) * facts_.height;
    std::vector<unsigned char> bytes(count * facts_.components);
    JpegFacts again;
    std::string error = decodeFile(path_, again, bytes.data());
    if (!error.empty()) return error;
    if (again.width != facts_.width || again.height != facts_.height ||
        again.components != facts_.components)
      return "the image changed while read";
    if (!facts_.cmyk) {
      for (size_t i = 0; i < bytes.size(); ++i) out[i] = byteToFloat(bytes[i]);
      return "";
    }
    for (size_t p = 0; p < count; ++p) {
      const unsigned char* cmyk = &bytes[4 * p];
      const float k = byteToFloat(cmyk[3]);
      for (int c = 0; c < 3; ++c)
        out[3 * p + c] = byteToFloat(floatToByte(byteToFloat(cmyk[c]) * k));
    }
    return "";
  }

 private:
  std::string path_;
  JpegFacts facts_;
  ImageHeader header_;
};

}  // namespace

bool isJpegFile(const std::string& path) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  unsigned char b[3] = {};
  const size_t n = std::fread(b, 1, sizeof b, file);
  std::fclose(file);
  return n == sizeof b && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF;
}

std::unique_ptr<ImageReader> openJpeg(const std::string& path, std::string& error) {
  JpegFacts facts;
  error = decodeFile(path, facts, nullptr);
  if (!error.empty()) return nullptr;
  if (facts.components != 1 && facts.components != 3 && !facts.cmyk) {
    error = "a JPEG of " + std::to_string(facts.components) + " components (1, 3 or CMYK are read)";
    return nullptr;
  }
  return std::make_unique<JpegReader>(path, facts);
}

}  // namespace lucent::builtin
