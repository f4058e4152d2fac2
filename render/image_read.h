// Reading image files (image textures, bump and height maps): every format through
// OpenImageIO (the plugin of images/image_plugin.h, loaded on first use), refusing from the
// header alone what cannot be read. Writing the output image is the application's
// (app/image_output.h).
#pragma once

#include "image.h"

#include "scenegraph/gamma_curve.h"

#include <optional>
#include <stdexcept>
#include <string>

namespace lucent {

// A file that cannot be written or read; the message names the file and the reason.
struct ImageIOError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// How readImageFile() returns integer-encoded pixels.
enum class PixelDecoding {
  Linear,    // decoded from sRGB to linear RGB (float formats are returned as stored)
  AsStored,  // the stored code values scaled to [0,1] (v/255, v/65535), no colour decoding
  // As Linear, with the colour divided by its alpha first: the readers premultiply it as
  // OpenImageIO does, POV-Ray's image_map shows the colour as stored (an <image> that reads
  // its transparency with use-alpha).
  StraightLinear
};

// Opens the file and reads its header only, throwing ImageIOError for everything
// readImageFile() would refuse from the header (not an image, no pixels, too large).
void checkImageFile(const std::string& path);

// Reads the first three channels (a grey image is repeated into all three). `fileGamma`,
// with a Linear or StraightLinear decoding: the curve the file's values encode light with,
// in place of what the file says (integer and float files alike).
Image readImageFile(const std::string& path, PixelDecoding decoding = PixelDecoding::Linear,
                    const std::optional<GammaCurve>& fileGamma = std::nullopt);

}  // namespace lucent
