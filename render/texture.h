// Texture colours T at a surface point: the solid 3-D checker and image maps.
#pragma once

#include "scenegraph/located_error.h"
#include "scenegraph/map_blend.h"
#include "scenegraph/material.h"
#include "scenegraph/render_settings.h"

#include "image_read.h"

#include "primitives/hit.h"
#include "primitives/instance.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace lucent {

// POV-Ray's checker: cell (⌊x⌋ + ⌊y⌋ + ⌊z⌋) mod 2 of p/scale, even cells (among them
// [0, scale)^3) are color1. A point on a cell boundary belongs to the cell on the positive
// side (the contract's rule, as POV-Ray's ⌊x + 1e-10⌋): the coordinates are nudged
// towards +∞ by more than their rounding error (`pError`, the bound of pObject's error in
// object units) but by no less than 1e-9 of the point's magnitude, so a plane y = 0 whose
// computed hit lies a hair below 0 still shows the cell above it.
Color checkerColor(const CheckerTexture& checker, const Vec3& pObject, const Vec3& pError);
// The same cell as 0 (color1's) or 1 (color2's).
int checkerIndex(const CheckerTexture& checker, const Vec3& pObject, const Vec3& pError);

// The colour with its filter and transmit of a texture other than an image at an object
// point (pError: its error bound, as checkerColor's). A point with no texture is white.
// The pixels of the images among the entries of maps and lists of pigments, by file
// (scenegraph/images_in_maps.h): the tracer shades copies of a material (see-through, layers),
// whose entries are the same images elsewhere. TextureSet loads them with the materials' own.
class ImageMap;
using NestedImages = std::unordered_map<std::string, std::shared_ptr<const ImageMap>>;
// An image's key among them: its path, marked where its colours are read straight (an
// image that reads its transparency) or decoded with a gamma of its own, since the file's
// pixels are then loaded otherwise.
std::string imageKey(const ImageTexture& image);

// `images`: the pixels of the images among the texture's entries (null where it holds none:
// a sky's, a pigment function's). `uvPoint`: the surface's (u, v, 0), which uv-mapped entries
// read (null away from a surface, where none may be uv-mapped).
PigmentColor pigmentAt(const Texture& texture, const Vec3& pObject, const Vec3& pError,
                       const NestedImages* images = nullptr, const Vec3* uvPoint = nullptr);

// The value a material map's pattern takes at a hit (scenegraph/map_blend.h): a <pattern>'s
// value, or the cell of a <checker> (0, 1), <hexagon> (0, 1, 2) or <brick> (0 mortar,
// 1 brick).
double mapValueAt(const Texture& pattern, const SurfaceInfo& surface, const Instance& leaf);

// The entries a material map shows at a hit: those its pattern's value falls between, or for
// an image read by index the one entry its material number picks (scenegraph/map_blend.h).
MapBlend mapChoice(const Material& m, const SurfaceInfo& surface, const Instance& leaf);

// An image looked up bilinearly at (u, v), repeating outside [0,1]^2 (v = 0 is the
// bottom row of the image, v = 1 the top, as in OpenGL and Mitsuba). 8-bit images and
// those tagged sRGB are decoded to linear RGB once, on load.
class ImageMap {
 public:
  // Throws ImageIOError naming the file. A bump map keeps the stored values
  // (PixelDecoding::AsStored), as POV-Ray reads bump_map images without gamma.
  // `fileGamma`: the curve the file's values are decoded with (readImageFile).
  explicit ImageMap(const std::string& path, PixelDecoding decoding = PixelDecoding::Linear,
                    const std::optional<GammaCurve>& fileGamma = std::nullopt);
  // Pixels already read (and converted).
  explicit ImageMap(Image pixels);
  ~ImageMap();
  ImageMap(const ImageMap&) = delete;
  ImageMap& operator=(const ImageMap&) = delete;

  // `scale` enlarges the image on the surface: one copy covers scale.x by scale.y of (u,v).
  Color lookup(const Vec2& uv, const Vec2& scale) const;
  // The same bilinear lookup at pixel coordinates: (x, y) = (i + ½, j + ½) is the centre
  // of the pixel in column i, row j (row 0 the top), repeating.
  Color lookupPixel(double x, double y) const;
  int width() const;
  int height() const;
  // The decoded pixels (linear RGB, or as stored for a bump map), row 0 the top.
  const Image& pixels() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Reads the header of every <image> texture's and <bump-map>'s file (of the materials and
// their layers), as `lucent check` does: throws
// what TextureSet would for a file that is not an image or too large (LocatedError, Kind::Input).
void checkImageTextures(const std::vector<Material>& materials);

class ImageMapCache;  // image_map_cache.h

// The image maps of a scene's surfaces, each file loaded once, indexed by slot (a material,
// or a layer of one: render/surface_slots.h).
class TextureSet {
 public:
  // Loads every <image> texture and <bump-map>, or takes it from `cache` (which keeps it
  // for later sets); throws LocatedError (Kind::Input, at the element) for one that cannot
  // be read.
  // Under a working gamma other than linear (POV-Ray's assumed_gamma) an image texture's
  // texels are encoded with it, as POV-Ray reads image maps; bump maps stay as stored.
  explicit TextureSet(const std::vector<const Material*>& surfaces, ImageMapCache* cache = nullptr,
                      const WorkingGamma& gamma = {});

  // The texture colour T of slot `index` at the hit (1 for a material without one).
  Color eval(uint32_t index, const Material& material, const SurfaceInfo& surface,
             const Instance& leaf) const;

  // The same with the colour's filter and transmit (an image's are 0): for the materials
  // whose texture is see-through (textureSeeThrough), which alone pay for it.
  PigmentColor evalPigment(uint32_t index, const Material& material, const SurfaceInfo& surface,
                           const Instance& leaf) const;

  // The <bump-map> image of material `index` (stored values), null if it has none.
  const ImageMap* bumpMap(uint32_t index) const { return bumpMaps_[index].get(); }

 private:
  std::vector<std::shared_ptr<const ImageMap>> maps_;      // per material; null if no image
  std::vector<std::shared_ptr<const ImageMap>> bumpMaps_;  // per material; null if none
  NestedImages nested_;  // the images among the entries of every material's maps and lists
};

}  // namespace lucent
