#include "pov_image_map.h"

#include "pov_patterns.h"

#include "images/image_plugin.h"

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <utility>

namespace lucent {

std::string povImageFormat(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".png") return "png";
  if (ext == ".jpg" || ext == ".jpeg") return "jpeg";
  if (ext == ".tif" || ext == ".tiff") return "tiff";
  if (ext == ".exr") return "exr";
  if (ext == ".hdr") return "hdr";
  if (ext == ".ppm") return "ppm";
  if (ext == ".pgm") return "pgm";
  if (ext == ".gif") return "gif";
  if (ext == ".tga") return "tga";
  if (ext == ".bmp") return "bmp";
  return "";
}

namespace {

// A matrix whose columns (the images of x, y, z) are a, b, c.
Mat4 basis(const Vec3& a, const Vec3& b, const Vec3& c) {
  Mat4 m(1.0);
  m[0] = Vec4(a, 0.0);
  m[1] = Vec4(b, 0.0);
  m[2] = Vec4(c, 0.0);
  return m;
}

// What Lucent decodes (render/texture.cpp): sRGB when OpenImageIO says so, or for 8-bit
// files that say nothing; the rest is taken as linear. POV-Ray is told the same explicitly.
// Also reports an alpha channel, which POV-Ray would turn into transparency.
struct ImageFacts {
  bool readable = false;
  bool srgb = false;
  bool floating = false;
  bool alpha = false;
};

ImageFacts imageFacts(const std::string& path) {
  ImageFacts f;
  std::string error;
  std::unique_ptr<ImageReader> in = imagePlugin().openFile(path, error);
  if (!in) return f;
  const ImageHeader& h = in->header();
  f.readable = true;
  f.srgb = h.saysSrgb() || (h.colorSpace.empty() && h.eightBit);
  f.floating = h.floating;
  f.alpha = h.alphaChannel >= 0 || h.channels == 2 || h.channels == 4;
  return f;
}

// `image_map { FORMAT "file" gamma map_type once interpolate filter all transmit all
// filter N, F ... }`: the material's filter and transmit added to the image's own (POV-Ray
// 3.7 adds `all` to every pixel) and to its palette entries' own.
std::string imageMapText(const ImageTexture& image, const std::string& format,
                         const ImageFacts& facts, int mapType, double filter, double transmit) {
  static const char* const kInterpolate[] = {"", " interpolate 2", " interpolate 3",
                                             " interpolate 4"};
  std::string absolute = std::filesystem::absolute(image.path).lexically_normal().string();
  std::string map = fmt::format("{} {{ {} {}", ImageTexture::kind.pov, format, povString(absolute));
  if (image.fileGamma)
    map += image.fileGamma->srgb ? " gamma srgb" : " gamma " + povFloat(image.fileGamma->power);
  else if (!facts.floating) map += facts.srgb ? " gamma srgb" : " gamma 1.0";
  if (mapType != 0) map += " map_type " + std::to_string(mapType);
  if (image.once) map += " once";
  map += kInterpolate[static_cast<int>(image.interpolation)];
  filter += image.all.filter;
  transmit += image.all.transmit;
  if (filter != 0.0) map += " filter all " + povFloat(filter);
  if (transmit != 0.0) map += " transmit all " + povFloat(transmit);
  // An entry's own values after `all`, which would set every entry's.
  for (const PaletteEntryFT& e : image.palette) {
    if (e.filter)
      map +=
          fmt::format(" filter {}, {}", e.index, povFloat(*e.filter + filter - image.all.filter));
    if (e.transmit)
      map += fmt::format(" transmit {}, {}", e.index,
                         povFloat(*e.transmit + transmit - image.all.transmit));
  }
  return map + " }";
}

// The image's format and facts, or an error naming it (then nothing).
std::optional<std::pair<std::string, ImageFacts>> readableImage(const ImageTexture& image,
                                                                const std::string& materialName,
                                                                PovIssues& issues) {
  std::string format = povImageFormat(image.path);
  if (format.empty()) {
    issues.error(image.loc,
                 fmt::format("{}: POV-Ray cannot read the image '{}'", materialName, image.path));
    return std::nullopt;
  }
  ImageFacts facts = imageFacts(image.path);
  if (!facts.readable) {
    issues.error(image.loc,
                 fmt::format("{}: cannot read the image '{}'", materialName, image.path));
    return std::nullopt;
  }
  if (facts.alpha && !image.useAlpha)
    issues.warning(image.loc, fmt::format("{}: the image '{}' has an alpha channel, which "
                                          "POV-Ray uses as transparency and this <image> "
                                          "ignores (use-alpha=\"true\" reads it)",
                                          materialName, image.path));
  return std::make_pair(format, facts);
}

}  // namespace

bool checkNestedImage(const ImageTexture& image, const std::string& materialName,
                      PovIssues& issues) {
  if (!readableImage(image, materialName, issues)) return false;
  if (image.projection == ImageProjection::uv) {
    issues.error(image.loc, materialName +
                                ": an image at (u,v) inside a map or a list of "
                                "pigments, which POV-Ray reads at its map's point");
    return false;
  }
  return true;
}

void writeNestedImageBody(const ImageTexture& image, double filter, double transmit,
                          PovWriter& out) {
  static const int kMapType[] = {0, 0, 1, 2, 5};
  out.line(imageMapText(image, povImageFormat(image.path), imageFacts(image.path),
                        kMapType[static_cast<int>(image.projection)], filter, transmit));
  writePlacement(image.placement, out);
}

void writeProjectedImagePigment(const ImageTexture& image, double filter, double transmit,
                                const std::string& materialName, PovWriter& out,
                                PovIssues& issues) {
  const auto readable = readableImage(image, materialName, issues);
  if (!readable) return;
  // POV-Ray's map_type of each projection (the enum's order: uv, planar, spherical, ...).
  static const int kMapType[] = {0, 0, 1, 2, 5};
  out.open("pigment");
  writeUvMapping(image.placement, out);
  out.line(imageMapText(image, readable->first, readable->second,
                        kMapType[static_cast<int>(image.projection)], filter, transmit));
  writePlacement(image.placement, out);
  out.close();
}

void writeImagePigment(const ImageTexture& image, double filter, double transmit,
                       const ImageMapping& mapping, const char* shapeName, const SourceLoc& loc,
                       const std::string& materialName, PovWriter& out, PovIssues& issues) {
  const auto readable = readableImage(image, materialName, issues);
  if (!readable) return;
  const auto& [format, facts] = *readable;
  if (mapping.kind == ImageMapping::None) {
    issues.error(loc, fmt::format("<{}> with the image texture of {}: POV-Ray has no mapping "
                                  "equal to Lucent's (u,v) for it (plane, disc, box, sphere "
                                  "and meshes with uvs can be exported)",
                                  shapeName, materialName));
    return;
  }
  const bool unitScale = image.scale.x == 1.0 && image.scale.y == 1.0;
  if (mapping.kind == ImageMapping::Spherical && !unitScale) {
    issues.error(loc, fmt::format("<{}> with the image texture of {}: POV-Ray's spherical "
                                  "map covers the sphere once; image scale {} {} has no "
                                  "equivalent",
                                  shapeName, materialName, image.scale.x, image.scale.y));
    return;
  }

  const std::string map = imageMapText(
      image, format, facts, mapping.kind == ImageMapping::Spherical ? 1 : 0, filter, transmit);

  // Lucent reads the image at (u / scale.x, v / scale.y).
  const Vec3 scale(image.scale.x, image.scale.y, 1.0);
  out.open("pigment");
  switch (mapping.kind) {
    case ImageMapping::MeshUV:
      // The pattern is evaluated at (u, v, 0): x, y of the planar map.
      out.line("uv_mapping");
      out.line(map);
      if (!unitScale) out.line("scale " + povVector(scale));
      break;
    case ImageMapping::Spherical:
      // Pattern point q = R(p − c) with R(x, y, z) = (−z, y, −x), its own inverse: then
      // POV-Ray's longitude (from +x towards +z) is Lucent's atan2(x, z) + π and its
      // latitude 0.5 + asin(q.y)/π (0 at the image's bottom row) is Lucent's
      // v = 1 − acos(y/r)/π (v = 1 at the +y pole, primitives/sphere.cpp).
      out.line(map);
      out.line(povMatrix(basis(Vec3(0, 0, -1), Vec3(0, 1, 0), Vec3(-1, 0, 0))));
      if (mapping.center != Vec3(0.0)) out.line("translate " + povVector(mapping.center));
      break;
    case ImageMapping::Planar: {
      // POV-Ray evaluates the pattern at T⁻¹·p and reads the planar map at its x, y; so
      // T⁻¹ = scale⁻¹ · uvFromObject.
      Mat4 inverseScale = glm::scale(Mat4(1.0), 1.0 / scale);
      out.line(map);
      out.line(povMatrix(glm::inverse(inverseScale * mapping.uvFromObject)));
      break;
    }
    case ImageMapping::None:
      break;
  }
  out.close();
}

void writeProjectedBumpMapNormal(const BumpMapSpec& bump, const std::string& materialName,
                                 PovWriter& out, PovIssues& issues) {
  std::string format = povImageFormat(bump.path);
  ImageFacts facts = imageFacts(bump.path);
  if (format.empty() || !facts.readable) {
    issues.error(bump.loc,
                 fmt::format("{}: POV-Ray cannot read the bump map '{}'", materialName, bump.path));
    return;
  }
  static const int kMapType[] = {0, 0, 1, 2, 5};
  static const char* const kInterpolate[] = {"", " interpolate 2", " interpolate 3",
                                             " interpolate 4"};
  std::string absolute = std::filesystem::absolute(bump.path).lexically_normal().string();
  std::string map = fmt::format("bump_map {{ {} {}", format, povString(absolute));
  if (!facts.floating) map += " gamma 1.0";
  map += " map_type " + std::to_string(kMapType[static_cast<int>(bump.projection)]);
  if (bump.once) map += " once";
  map += kInterpolate[static_cast<int>(bump.interpolation)];
  map += bump.useIndex ? " use_index }" : " use_color }";
  out.open("normal");
  out.line(map);
  out.line("bump_size " + povNumber(bump.depth));
  writePlacement(bump.placement, out);
  out.close();
}

void writeBumpMapNormal(const BumpMapSpec& bump, const ImageMapping& mapping, const char* shapeName,
                        const SourceLoc& loc, const std::string& materialName, PovWriter& out,
                        PovIssues& issues) {
  std::string format = povImageFormat(bump.path);
  if (format.empty()) {
    issues.error(bump.loc,
                 fmt::format("{}: POV-Ray cannot read the bump map '{}'", materialName, bump.path));
    return;
  }
  ImageFacts facts = imageFacts(bump.path);
  if (!facts.readable) {
    issues.error(bump.loc,
                 fmt::format("{}: cannot read the bump map '{}'", materialName, bump.path));
    return;
  }
  if (mapping.kind != ImageMapping::MeshUV && mapping.kind != ImageMapping::Spherical) {
    issues.error(loc, fmt::format("<{}> with the bump map of {}: POV-Ray's bump_map bends the "
                                  "normal as Lucent's only with uv_mapping, whose (u,v) equal "
                                  "Lucent's only on meshes with uvs and on spheres",
                                  shapeName, materialName));
    return;
  }
  std::string absolute = std::filesystem::absolute(bump.path).lexically_normal().string();
  std::string map = fmt::format("bump_map {{ {} {}", format, povString(absolute));
  if (!facts.floating) map += " gamma 1.0";
  static const char* const kInterpolate[] = {"", " interpolate 2", " interpolate 3",
                                             " interpolate 4"};
  if (bump.once) map += " once";
  map += kInterpolate[static_cast<int>(bump.interpolation)];
  map += bump.useIndex ? " use_index }" : " use_color }";
  out.open("normal");
  out.line("uv_mapping");
  out.line(map);
  out.line("bump_size " + povNumber(bump.depth));
  if (mapping.kind == ImageMapping::Spherical) {
    // POV-Ray's sphere has u_P = longitude from +x towards +z, Lucent's u = 0.75 - u_P
    // (primitives/sphere.cpp), and both have the same v. The pattern point (u_P, v, 0) is
    // carried to (0.75 - u_P, v, 0) by a half turn about y, not a mirror: POV-Ray turns the
    // normal into the pattern's space and back around the bump, and a half turn leaves the
    // bump frame (built from the normal and +y) as Lucent's, where a mirror would flip it.
    out.line("scale <-1, 1, -1>");
    out.line("translate <0.75, 0, 0>");
  }
  out.close();
}

}  // namespace lucent
