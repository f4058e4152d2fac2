// Image files through OpenImageIO: writing encoded pixels, reading headers and pixels.
#include "oiio_parts.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstring>

namespace lucent::oiio {

namespace {

OIIO::TypeDesc typeOf(StoredType t) {
  switch (t) {
    case StoredType::UInt8:
      return OIIO::TypeDesc::UINT8;
    case StoredType::UInt16:
      return OIIO::TypeDesc::UINT16;
    case StoredType::Float:
      return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::UNKNOWN;
}

class FileReader final : public ImageReader {
 public:
  explicit FileReader(std::unique_ptr<OIIO::ImageInput> in) : in_(std::move(in)) {
    const OIIO::ImageSpec& spec = in_->spec();
    header_.width = spec.width;
    header_.height = spec.height;
    header_.channels = spec.nchannels;
    header_.eightBit = spec.format.basetype == OIIO::TypeDesc::UINT8;
    header_.sixteenBit = spec.format.basetype == OIIO::TypeDesc::UINT16;
    header_.floating = spec.format.is_floating_point();
    header_.alphaChannel = spec.alpha_channel;
    // OpenImageIO 2.4's GIF reader names the channel past the last (4 of R, G, B, A) as
    // alpha: then the channel called A is.
    if (header_.alphaChannel >= spec.nchannels) {
      header_.alphaChannel = -1;
      for (int c = 0; c < spec.nchannels; ++c)
        if (spec.channel_name(c) == "A") header_.alphaChannel = c;
    }
    header_.colorSpace = spec.get_string_attribute("oiio:ColorSpace");
  }
  ~FileReader() override { in_->close(); }

  const ImageHeader& header() const override { return header_; }

  std::string readPixels(float* out) override {
    if (!in_->read_image(0, 0, 0, header_.channels, OIIO::TypeDesc::FLOAT, out)) {
      std::string reason = in_->geterror();
      return reason.empty() ? "the pixels cannot be read" : reason;
    }
    return "";
  }

 private:
  std::unique_ptr<OIIO::ImageInput> in_;
  ImageHeader header_;
};

}  // namespace

WriteFailure writeFile(const std::string& path, const ImageToWrite& image) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, typeOf(image.type));
  if (!image.colorSpace.empty()) spec.attribute("oiio:ColorSpace", image.colorSpace);
  if (!image.compression.empty()) spec.attribute("compression", image.compression);
  if (image.pnmBinary) spec.attribute("pnm:binary", 1);

  auto out = OIIO::ImageOutput::create(image.format);
  if (!out) return {WriteFailure::Create, OIIO::geterror()};
  auto failure = [&](WriteFailure::Step step) {
    std::string why = out->geterror();
    if (why.empty()) why = std::strerror(errno);
    return WriteFailure{step, why};
  };
  errno = 0;
  if (!out->open(path, spec)) return failure(WriteFailure::Create);
  if (!out->write_image(spec.format, image.pixels)) return failure(WriteFailure::Write);
  if (!out->close()) return failure(WriteFailure::Write);
  return {};
}

std::unique_ptr<ImageReader> openFile(const std::string& path, std::string& error) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = OIIO::geterror();
    if (error.empty()) error = "not an image file OpenImageIO can read";
    return nullptr;
  }
  return std::make_unique<FileReader>(std::move(in));
}

std::string srgbToLinear(float* pixels, int width, int height, int channels) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf encoded(spec, pixels);  // wraps the pixels, no copy
  OIIO::ImageBuf decoded =
      OIIO::ImageBufAlgo::colorconvert(encoded, "sRGB", "linear", /*unpremult=*/false);
  if (decoded.has_error()) return decoded.geterror();
  if (!decoded.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT,
                          pixels))
    return decoded.geterror();
  return "";
}

}  // namespace lucent::oiio
