// GIF files read through giflib, as POV-Ray 3.7 reads a GIF (its base/image/gif.cpp, read
// for the facts): the first image of the file, a palette image whose colours are the
// palette's (the image's own colour table, else the file's), an entry of alpha 0 where a
// graphic control extension before the image marks its index transparent. POV-Ray refuses
// an interlaced GIF and one without a global table; giflib reads both, and so does Lucent.
#include "builtin_images.h"
#include "builtin_readers.h"

#include <gif_lib.h>

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

namespace lucent {

bool isGifFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  char magic[6] = {};
  if (!f.read(magic, sizeof magic)) return false;
  return std::memcmp(magic, "GIF87a", 6) == 0 || std::memcmp(magic, "GIF89a", 6) == 0;
}

namespace {

// The most pixels `bytes` of LZW data can give: a code takes at least 3 bits and stands for
// at most 4096 pixels. A header that claims more is a damaged file, refused before its
// pixels are allocated (a 100-byte file cannot make 4 GB).
std::uintmax_t mostPixels(std::uintmax_t bytes) { return bytes * 8 / 3 * 4096 + 4096; }

std::string damaged(const GifFileType& gif) {
  return fmt::format("a damaged GIF: {}", GifErrorString(gif.Error));
}

// The first image's indices into `out` (rows top first, de-interlaced), after the
// extensions before it: the graphic control extension's transparent index.
std::string readFirstImage(GifFileType& gif, std::uintmax_t fileBytes, GifPixels& out) {
  GraphicsControlBlock control{};
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  bool controlRead = false;
  for (;;) {
    GifRecordType type;
    if (DGifGetRecordType(&gif, &type) == GIF_ERROR) return damaged(gif);
    if (type == TERMINATE_RECORD_TYPE) return "the GIF holds no image";
    if (type == EXTENSION_RECORD_TYPE) {
      int code = 0;
      GifByteType* block = nullptr;
      if (DGifGetExtension(&gif, &code, &block) == GIF_ERROR) return damaged(gif);
      if (code == GRAPHICS_EXT_FUNC_CODE && block && !controlRead)
        controlRead = DGifExtensionToGCB(block[0], block + 1, &control) == GIF_OK;
      while (block)
        if (DGifGetExtensionNext(&gif, &block) == GIF_ERROR) return damaged(gif);
      continue;
    }
    if (type != IMAGE_DESC_RECORD_TYPE) continue;
    if (DGifGetImageDesc(&gif) == GIF_ERROR) return damaged(gif);
    const GifImageDesc& desc = gif.Image;
    if (desc.Width <= 0 || desc.Height <= 0) return "the GIF's image has no pixels";
    const std::uintmax_t pixels = std::uintmax_t(desc.Width) * std::uintmax_t(desc.Height);
    if (pixels > mostPixels(fileBytes))
      return fmt::format("a damaged GIF: a {}x{} image in a file of {} bytes", desc.Width,
                         desc.Height, fileBytes);
    const ColorMapObject* table = desc.ColorMap ? desc.ColorMap : gif.SColorMap;
    if (!table) return "the GIF has no colour table";
    out.width = desc.Width;
    out.height = desc.Height;
    out.paletteColours.clear();
    for (int i = 0; i < table->ColorCount; ++i) {
      const GifColorType& c = table->Colors[i];
      out.paletteColours.push_back({c.Red, c.Green, c.Blue, 255});
    }
    out.transparentIndex = control.TransparentColor != NO_TRANSPARENT_COLOR &&
                           control.TransparentColor < table->ColorCount;
    if (out.transparentIndex) out.paletteColours[size_t(control.TransparentColor)][3] = 0;
    out.indices.assign(static_cast<size_t>(pixels), 0);
    auto readRow = [&](int row) {
      return DGifGetLine(&gif, &out.indices[size_t(row) * size_t(desc.Width)], desc.Width) ==
             GIF_OK;
    };
    if (desc.Interlace) {
      // GIF's four passes: every 8th row from 0, every 8th from 4, every 4th from 2, every
      // 2nd from 1.
      const int first[4] = {0, 4, 2, 1}, step[4] = {8, 8, 4, 2};
      for (int pass = 0; pass < 4; ++pass)
        for (int row = first[pass]; row < desc.Height; row += step[pass])
          if (!readRow(row)) return damaged(gif);
    } else {
      for (int row = 0; row < desc.Height; ++row)
        if (!readRow(row)) return damaged(gif);
    }
    for (std::uint8_t index : out.indices)
      if (index >= table->ColorCount)
        return fmt::format("a pixel's palette index {} is beyond the GIF's {} colours", index,
                           table->ColorCount);
    return "";
  }
}

}  // namespace

std::string readGif(const std::string& path, GifPixels& out) {
  std::error_code sizeError;
  const std::uintmax_t bytes = std::filesystem::file_size(path, sizeError);
  if (sizeError) return sizeError.message();
  int error = 0;
  GifFileType* opened = DGifOpenFileName(path.c_str(), &error);
  if (!opened) return fmt::format("cannot read the GIF: {}", GifErrorString(error));
  const std::string reason = readFirstImage(*opened, bytes, out);
  int ignored = 0;
  DGifCloseFile(opened, &ignored);
  return reason;
}

namespace builtin {

namespace {

// The palette's colours as stored (a GIF's are straight: nothing to premultiply), with an
// alpha channel when an index is transparent; labelled sRGB, as OpenImageIO labels GIFs.
class GifReader final : public ImageReader {
 public:
  explicit GifReader(GifPixels pixels) : pixels_(std::move(pixels)) {
    header_.width = pixels_.width;
    header_.height = pixels_.height;
    header_.channels = pixels_.transparentIndex ? 4 : 3;
    header_.eightBit = true;
    header_.alphaChannel = pixels_.transparentIndex ? 3 : -1;
    header_.colorSpace = "sRGB";
  }

  const ImageHeader& header() const override { return header_; }

  std::string readPixels(float* out) override {
    const int n = header_.channels;
    for (size_t p = 0; p < pixels_.indices.size(); ++p) {
      const auto& c = pixels_.paletteColours[pixels_.indices[p]];
      for (int k = 0; k < n; ++k) out[p * n + k] = static_cast<float>(c[k]) * (1.0f / 255.0f);
    }
    return "";
  }

 private:
  GifPixels pixels_;
  ImageHeader header_;
};

}  // namespace

std::unique_ptr<ImageReader> openGif(const std::string& path, std::string& error) {
  GifPixels pixels;
  error = readGif(path, pixels);
  if (!error.empty()) return nullptr;
  return std::make_unique<GifReader>(std::move(pixels));
}

}  // namespace builtin

}  // namespace lucent
