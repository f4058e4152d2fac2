// `image_map { [TYPE] "file" [gamma G] modifiers }` in a pigment: Lucent's <image> projected
// from pattern space as POV-Ray 3.7 projects it (render/image_projection.h), placed by the
// pigment's transforms like any pattern (docs/povray-import.md, "Image maps").
#include "pov_image_gamma.h"
#include "read_support.h"
#include "scene_reader.h"

#include "images/builtin/builtin_images.h"
#include "images/image_values_file.h"
#include "lang/expression.h"
#include "scenegraph/image_pattern.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

namespace {

// The file types POV-Ray names and the extensions it tries for each; empty: a type whose
// files Lucent does not read.
const std::map<std::string_view, std::vector<std::string>>& imageTypes() {
  static const std::map<std::string_view, std::vector<std::string>> kTypes = {
      {"png", {".png", ".PNG"}},
      {"jpeg", {".jpg", ".JPG", ".jpeg", ".JPEG"}},
      {"tiff", {".tif", ".TIF", ".tiff", ".TIFF"}},
      {"tga", {".tga", ".TGA"}},
      {"ppm", {".ppm", ".PPM"}},
      {"pgm", {".pgm", ".PGM"}},
      {"exr", {".exr", ".EXR"}},
      {"hdr", {".hdr", ".HDR"}},
      {"bmp", {".bmp", ".BMP"}},
      {"gif", {".gif", ".GIF"}},
      {"iff", {}},
      {"sys", {}},
      {"pot", {}}};
  return kTypes;
}

// POV-Ray's map_type numbers; the others (3 parabolic, 4 hyperbolic, 6, 7) it refuses too.
std::optional<ImageProjection> projectionOf(double mapType) {
  switch (static_cast<int>(mapType)) {
    case 0:
      return ImageProjection::planar;
    case 1:
      return ImageProjection::spherical;
    case 2:
      return ImageProjection::cylindrical;
    case 5:
      return ImageProjection::torus;
    default:
      return std::nullopt;
  }
}

// Whether the file may be a palette image, whose indices POV-Ray reads where a bump map says
// use_index: a palette PNG, a GIF, or a format that can hold a palette whose indices
// OpenImageIO hides (TGA, BMP, TIFF); JPEG, PPM, PGM, EXR and HDR cannot.
bool mayHoldPalette(const std::string& path) {
  if (isGifFile(path)) return true;
  if (isPngFile(path)) {
    PngPixels png;
    return !readPngHeader(path, png).empty() || png.palette;
  }
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return !(ext == ".jpg" || ext == ".jpeg" || ext == ".ppm" || ext == ".pgm" || ext == ".exr" ||
           ext == ".hdr");
}

}  // namespace

// `[TYPE] "file" [gamma G] [premultiplied B]`: the file's path, found as an include is.
SceneReader::ImageFileSpec SceneReader::readImageFileSpec(TokenStream& in) {
  const Token type = in.next();
  if (isWord(type, "function"))
    in.error(type,
             "'image_map { function }' is not supported by Lucent (images made by a "
             "function; it reads image files)");
  const auto& types = imageTypes();
  const auto known = type.kind == TokenKind::Keyword ? types.find(type.text()) : types.end();
  if (known != types.end() && known->second.empty())
    in.error(type, "image maps from '" + std::string(type.text()) +
                       "' files are not supported by Lucent (it reads png, jpeg, tiff, tga, "
                       "ppm, pgm, exr, hdr, bmp and gif images)");
  if (known == types.end()) in.unget();  // a file name alone: its extension, else png
  const SourceLoc fileLoc = in.peek().loc();
  const std::string name = in.parseString();
  std::vector<std::string> extensions =
      known != types.end() ? known->second : std::vector<std::string>{};
  // POV-Ray takes a name without an extension as its output type's file (png here).
  if (known == types.end() && std::filesystem::path(name).extension().empty())
    extensions = types.at("png");
  ImageFileSpec spec;
  spec.path = in.findDataFile(name, fileLoc, extensions).string();
  spec.format = known != types.end() ? std::string(known->first)
                : std::filesystem::path(name).extension().empty()
                    ? "png"
                    : std::filesystem::path(name).extension().string();
  for (;;) {
    if (isWord(in.peek(), "gamma")) {
      const Token k = in.next();
      spec.gammaLoc = k.loc();
      if (isWord(in.peek(), "srgb")) {
        in.next();
        spec.gamma = GammaCurve{true, 1.0};
        continue;
      }
      const double g = in.parseFloat();
      if (!(g > 0.0))
        in.error(k, "gamma " + formatNumber(g) + ": an image's gamma must be above 0");
      spec.gamma = GammaCurve{false, g};
    } else if (isWord(in.peek(), "premultiplied")) {
      in.next();
      in.parseFloat();
    } else {
      return spec;
    }
  }
}

std::string SceneReader::readStoredImageFile(TokenStream& in) {
  ImageFileSpec spec = readImageFileSpec(in);
  if (spec.gamma && !spec.gamma->linear())
    warn(in, spec.gammaLoc,
         std::string("the image's gamma ") +
             (spec.gamma->srgb ? "srgb" : formatNumber(spec.gamma->power)) +
             " is not read (Lucent reads a bump map's, an image pattern's and a material "
             "map's values as stored, as POV-Ray does without a gamma)");
  return spec.path;
}

// `map_type`, `once`, `interpolate`: what image_map and bump_map share; false if `k` is none.
template <class Spec>
bool readImageReading(const Token& k, TokenStream& in, Spec& spec) {
  const std::string_view w = k.kind == TokenKind::Keyword ? k.text() : "";
  if (w == "once") {
    spec.once = true;
  } else if (w == "map_type") {
    const double m = in.parseFloat();
    const auto projection = projectionOf(m);
    if (!projection)
      in.error(k, "map_type " + formatNumber(m) +
                      " is not one POV-Ray 3.7 projects an image by (0 planar, 1 spherical, "
                      "2 cylindrical, 5 torus)");
    spec.projection = *projection;
  } else if (w == "interpolate") {
    const double i = in.parseFloat();
    switch (static_cast<int>(i)) {
      case 2:
        spec.interpolation = ImageInterpolation::bilinear;
        break;
      case 3:
        spec.interpolation = ImageInterpolation::bicubic;
        break;
      case 4:
        spec.interpolation = ImageInterpolation::normalized;
        break;
      default:
        in.error(k, "interpolate " + formatNumber(i) +
                        " is not one POV-Ray takes (2 bilinear, 3 bicubic, 4 normalized "
                        "distance)");
    }
  } else if (w == "use_color" || w == "use_colour") {
    // POV-Ray's default for image and bump maps: the pixels' colours.
  } else {
    return false;
  }
  return true;
}

void SceneReader::readBumpMap(const Token& t, TokenStream& in, PovNormal& n) {
  in.expect("{");
  BumpMapSpec bump;
  bump.loc = t.loc();
  bump.projection = ImageProjection::planar;
  bump.interpolation = ImageInterpolation::none;  // POV-Ray's default
  bump.depth = n.spec.depth;
  bump.path = readStoredImageFile(in);
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) break;
    if (isWord(k, "use_color") || isWord(k, "use_colour")) {
      bump.useIndex = false;
      continue;
    }
    if (readImageReading(k, in, bump)) continue;
    if (isWord(k, "bump_size")) {
      bump.depth = in.parseFloat();
    } else if (isWord(k, "use_index")) {
      // POV-Ray takes a palette image's indices as heights; any other image has none, and
      // its grey levels are read as with use_color. The last of the two counts.
      bump.useIndex = true;
      if (mayHoldPalette(bump.path) && !readsPalette(bump.path))
        keepError(in, k.loc(),
                  "'use_index' on a palette image other than a PNG or GIF is not supported by "
                  "Lucent (it reads the palette indices of PNGs and GIFs)");
    } else if (isWord(k, "repeat") || isWord(k, "offset")) {
      keepError(in, k.loc(),
                "'" + std::string(k.text()) + "' in a bump map is not supported by Lucent");
      in.parseVector();
    } else {
      in.error(k, "'" + std::string(k.text()) + "' is not a bump_map modifier");
    }
  }
  if (bump.useIndex) {
    try {
      bump.indices = paletteIndices(bump.path);
    } catch (const std::exception& e) {
      in.error(t, "cannot read the bump map's palette indices in '" + bump.path + "': " + e.what());
    }
  }
  n.bump = bump;
}

// `image_pattern { [TYPE] "file" modifiers }`: its values read now, as the XML reader
// reads them (images/image_values_file.h). POV-Ray 3.7 reads the grey level with use_color
// (its default) and with use_index alike, for palette images too; use_alpha the
// transparency. The last of them counts.
std::shared_ptr<const ImagePattern> SceneReader::readImagePattern(TokenStream& in) {
  in.expect("{");
  ImagePattern im;
  const SourceLoc fileLoc = in.peek().loc();
  im.path = readStoredImageFile(in);
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) break;
    const std::string_view w = k.kind == TokenKind::Keyword ? k.text() : "";
    if (w == "use_alpha" || w == "use_color" || w == "use_colour" || w == "use_index") {
      im.useAlpha = w == "use_alpha";
    } else if (readImageReading(k, in, im)) {
      continue;
    } else if (w == "repeat" || w == "offset") {
      keepError(in, k.loc(),
                "'" + std::string(w) + "' in an image pattern is not supported by Lucent");
      in.parseVector();
    } else {
      in.error(k, "'" + std::string(k.text()) + "' is not an image_pattern modifier");
    }
  }
  try {
    im.values = readImagePatternValues(im.path, im.useAlpha);
  } catch (const std::exception& e) {
    in.error(fileLoc, "cannot read the image pattern's image '" + im.path + "': " + e.what());
  }
  return std::make_shared<const ImagePattern>(std::move(im));
}

// `material_map { [TYPE] "file" modifiers texture {..} texture {..} ... }`: a material map
// whose image-pattern is read by index (POV-Ray 3.7's Parse_Material_Map: the modifiers
// first, then at least one texture), its k-th texture shown where the image gives number k.
// The transforms after the block move the map (its textures lie in its space).
void SceneReader::readMaterialMap(const Token& t, TokenStream& in, PovTexture& tex) {
  if (!tex.below.empty())
    keepError(in, t.loc(),
              "a material_map over a layered texture (POV-Ray: \"Cannot layer over a patterned "
              "texture\")");
  in.expect("{");
  ImagePattern im;
  im.byIndex = true;
  const SourceLoc fileLoc = in.peek().loc();
  im.path = readStoredImageFile(in);
  std::vector<PovTextureMapEntry> entries;
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) break;
    const std::string_view w = k.kind == TokenKind::Keyword ? k.text() : "";
    if (w == "texture") {
      entries.push_back({double(entries.size()), readTexture(in, defaultTexture())});
    } else if (!entries.empty()) {
      in.error(k, "a texture or '}' expected after a material_map's textures, not " + k.describe());
    } else if (readImageReading(k, in, im)) {
      continue;
    } else if (w == "repeat" || w == "offset") {
      keepError(in, k.loc(),
                "'" + std::string(w) + "' in a material map is not supported by Lucent");
      in.parseVector();
    } else {
      in.error(k, "'" + std::string(k.text()) + "' is not a material_map modifier");
    }
  }
  if (entries.empty()) in.error(t, "a material_map needs at least one texture");
  try {
    im.values = readImageIndexValues(im.path);
  } catch (const std::exception& e) {
    in.error(fileLoc, "cannot read the material map's image '" + im.path + "': " + e.what());
  }
  PatternTexture pattern;
  pattern.pattern.type = PatternType::image;
  pattern.pattern.frequency = defaultFrequency(PatternType::image);
  pattern.pattern.image = std::make_shared<const ImagePattern>(std::move(im));
  PovPigment map;
  map.transform = tex.mapPattern.transform;
  map.pattern = std::move(pattern);
  tex.mapPattern = std::move(map);
  tex.mapEntries = std::move(entries);
  tex.name.clear();
}

// `filter INDEX, AMOUNT` (or `transmit`): the palette entry's own value, as POV-Ray 3.7's
// Parse_Image_Map sets it (the index rounded as it rounds it; its errors for an image
// without a palette and an index past the palette).
void SceneReader::readPaletteEntry(const Token& k, bool transmit, TokenStream& in,
                                   ImageTexture& image) {
  const SourceLoc at = in.peek().loc();
  const double raw = in.parseFloat() + 0.01;
  const int index = std::abs(raw) < 1e9 ? static_cast<int>(raw) : -1;  // NaN too: -1
  if (!image.paletteIndices) {
    const bool read = readsPalette(image.path);
    try {
      if (read) image.paletteIndices = paletteIndices(image.path);
    } catch (const std::exception& e) {
      in.error(k, "cannot read the palette of '" + image.path + "': " + e.what());
    }
    if (!image.paletteIndices && (read || !mayHoldPalette(image.path)))
      in.error(k, "Keyword '" + std::string(transmit ? "transmit" : "filter") +
                      "' cannot be used with non color-mapped image.");
    if (!read)
      keepError(in, k.loc(),
                "'" + std::string(k.text()) +
                    " INDEX, AMOUNT' on an image other than a PNG or GIF is not supported by "
                    "Lucent (it reads the palettes of PNGs and GIFs)");
  }
  const int size = image.paletteIndices ? image.paletteIndices->paletteSize : 256;
  if (index < 0 || index >= size)
    in.error(at, std::string(transmit ? "TRANSMIT" : "FILTER") +
                     " color register value out of range (the palette's " + std::to_string(size) +
                     " entries are 0 to " + std::to_string(size - 1) + ").");
  in.parseComma();
  const float amount = static_cast<float>(in.parseFloat());
  auto entry = std::find_if(image.palette.begin(), image.palette.end(),
                            [&](const PaletteEntryFT& e) { return e.index == index; });
  if (entry == image.palette.end())
    entry = image.palette.insert(image.palette.end(),
                                 PaletteEntryFT{index, std::nullopt, std::nullopt});
  (transmit ? entry->transmit : entry->filter) = amount;
}

void SceneReader::readImageMap(const Token& t, TokenStream& in, PovPigment& p) {
  in.expect("{");
  ImageTexture image;
  image.loc = t.loc();
  image.projection = ImageProjection::planar;
  image.interpolation = ImageInterpolation::none;  // POV-Ray's default
  if (const PatternPlacement* was = placementOf(p.pattern)) image.placement = *was;
  const ImageFileSpec file = readImageFileSpec(in);
  image.path = file.path;
  // The curve POV-Ray decodes the file with, whatever Lucent's own rule would take.
  image.fileGamma =
      povImageMapGamma(file.path, file.format, file.gamma, global_, in.effectiveLanguageVersion());
  bool transmitAll = false;

  for (;;) {
    const Token k = in.next();
    if (k.is("}")) break;
    const std::string_view w = k.kind == TokenKind::Keyword ? k.text() : "";
    if (readImageReading(k, in, image)) {
      continue;
    } else if (w == "use_index") {
      // POV-Ray 3.7's image_map reads its use_index and use_color flag nowhere: a palette
      // image shows its palette's colours either way.
    } else if (w == "filter" || w == "transmit" || w == "alpha") {
      const bool transmit = w == "transmit";
      if (!isWord(in.peek(), "all")) {
        readPaletteEntry(k, transmit, in, image);
        continue;
      }
      in.next();
      const float amount = static_cast<float>(in.parseFloat());
      (transmit ? image.all.transmit : image.all.filter) = amount;
      transmitAll = transmitAll || transmit;
      // POV-Ray sets every palette entry's value: an entry's own one given before is gone.
      for (PaletteEntryFT& e : image.palette) (transmit ? e.transmit : e.filter).reset();
    } else if (w == "repeat" || w == "offset") {
      keepError(in, k.loc(), "'" + std::string(w) + "' in an image map is not supported by Lucent");
      in.parseVector();
    } else {
      in.error(k, "'" + std::string(k.text()) + "' is not an image_map modifier");
    }
  }
  readImageAlpha(t, transmitAll, in, image);
  p.pattern = std::move(image);
  p.map.clear();
}

// POV-Ray 3.7's image_map takes the image's own transparency as each pixel's transmit,
// 1 − alpha, with `transmit all` added; on a palette image `transmit all` instead sets every
// entry's transmit, in place of its alpha (its Parse_Image_Map): each entry without one of
// its own then gets it as its own.
void SceneReader::readImageAlpha(const Token& t, bool transmitAll, TokenStream& in,
                                 ImageTexture& image) {
  try {
    image.useAlpha = true;
    image.alphaTransmit = readImageTransmit(image.path);
    if (!transmitAll || !image.alphaTransmit || !readsPalette(image.path)) return;
    if (!image.paletteIndices) image.paletteIndices = paletteIndices(image.path);
    if (!image.paletteIndices) return;
    for (int index = 0; index < image.paletteIndices->paletteSize; ++index) {
      auto own = std::find_if(image.palette.begin(), image.palette.end(),
                              [&](const PaletteEntryFT& e) { return e.index == index; });
      if (own == image.palette.end())
        image.palette.push_back({index, std::nullopt, image.all.transmit});
      else if (!own->transmit) own->transmit = image.all.transmit;
    }
    image.all.transmit = 0.0f;
  } catch (const std::exception& e) {
    keepError(in, t.loc(), "cannot read the transparency of '" + image.path + "': " + e.what());
  }
}

}  // namespace lucent::sdl
