// Which files the built-in part writes and reads, and the dispatch to its writers and readers.
#include "builtin_images.h"

#include "builtin_parts.h"
#include "builtin_readers.h"

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

std::unique_ptr<ImageReader> builtinOpenFile(const std::string& path, std::string& error) {
  error.clear();
  if (isPngFile(path)) return builtin::openPng(path, error);
  if (builtin::isJpegFile(path)) return builtin::openJpeg(path, error);
  if (isGifFile(path)) return builtin::openGif(path, error);
  return nullptr;
}

bool builtinReadsBackComplete(const std::string& path, const ImageToWrite& image) {
  return image.format == "png" ? builtin::pngReadsBackComplete(path, image)
                               : builtin::ppmReadsBackComplete(path, image);
}

}  // namespace lucent
