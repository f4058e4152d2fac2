// Which files the built-in part writes, and the dispatch to its writers.
#include "builtin_images.h"

#include "builtin_parts.h"

namespace lucent {

bool builtinWrites(const ImageToWrite& image) {
  if (image.format == "png")
    return (image.type == StoredType::UInt8 || image.type == StoredType::UInt16) &&
           (image.channels == 1 || image.channels == 3) &&
           (image.colorSpace == "sRGB" || image.colorSpace == "Linear");
  if (image.format == "pnm")
    return image.pnmBinary && image.type == StoredType::UInt8 && image.channels == 3;
  return false;
}

WriteFailure builtinWriteFile(const std::string& path, const ImageToWrite& image) {
  return image.format == "png" ? builtin::writePng(path, image) : builtin::writePpm(path, image);
}

bool builtinReadsBackComplete(const std::string& path, const ImageToWrite& image) {
  return image.format == "png" ? builtin::pngReadsBackComplete(path, image)
                               : builtin::ppmReadsBackComplete(path, image);
}

}  // namespace lucent
