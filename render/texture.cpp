#include "texture.h"
#include "scenegraph/images_in_maps.h"

#include "patterns/block_pattern.h"
#include "patterns/color_map.h"
#include "patterns/pattern_point.h"
#include "patterns/pattern_value.h"
#include "patterns/warp.h"

#include "image_map_cache.h"
#include "image_projection.h"
#include "image_read.h"
#include "uv_mapping.h"
#include "working_gamma.h"

#include "images/periodic_bilinear.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace lucent {

int checkerIndex(const CheckerTexture& checker, const Vec3& pObject, const Vec3& pError) {
  Vec3 q = pObject / checker.scale;
  Vec3 err = pError / checker.scale;
  // A surface lying on a cell boundary (a floor at y = 0) must fall on one side for every
  // pixel: each coordinate is nudged up by its error bound, and at least by 64 ulps of
  // the point's size (in cells, at least 1) for points whose bound is 0. A relative nudge
  // larger than rounding would repaint thin slivers along every boundary far from the
  // origin (1e-9 at x = 1e5 was 1e-4 units, docs/accuracy.md).
  double magnitude = std::max(1.0, maxComponent(glm::abs(q)));
  long sum = 0;
  for (int i = 0; i < 3; ++i) {
    double nudge = std::max(64.0 * kMachineEps * magnitude, 4.0 * err[i]);
    sum += static_cast<long>(std::floor(q[i] + nudge));
  }
  return static_cast<int>(sum & 1);
}

Color checkerColor(const CheckerTexture& checker, const Vec3& pObject, const Vec3& pError) {
  return checkerIndex(checker, pObject, pError) == 0 ? checker.color1 : checker.color2;
}

struct ImageMap::Impl {
  Image linear;                               // RGB, linear (or as stored, for bump maps)
  std::unique_ptr<PeriodicBilinear> sampler;  // the bilinear lookup of `linear`
};

std::string imageKey(const ImageTexture& image) {
  std::string key = image.alphaTransmit ? image.path + "\n(straight)" : image.path;
  if (image.fileGamma) key += "\n(" + curveText(*image.fileGamma) + ")";
  return key;
}

ImageMap::ImageMap(const std::string& path, PixelDecoding decoding,
                   const std::optional<GammaCurve>& fileGamma)
    : ImageMap(readImageFile(path, decoding, fileGamma)) {}

ImageMap::ImageMap(Image pixels) : impl_(std::make_unique<Impl>()) {
  impl_->linear = std::move(pixels);
  static_assert(sizeof(Color) == 3 * sizeof(float), "Image pixels are packed RGB floats");
  impl_->sampler = std::make_unique<PeriodicBilinear>(&impl_->linear.pixels[0][0],
                                                      impl_->linear.width, impl_->linear.height);
}

ImageMap::~ImageMap() = default;

int ImageMap::width() const { return impl_->linear.width; }
int ImageMap::height() const { return impl_->linear.height; }
const Image& ImageMap::pixels() const { return impl_->linear; }

Color ImageMap::lookup(const Vec2& uv, const Vec2& scale) const {
  float s = static_cast<float>(uv.x / scale.x);
  float t = static_cast<float>(1.0 - uv.y / scale.y);  // image row 0 is the top (v = 1)
  Color c;
  impl_->sampler->lookup(s, t, &c[0]);
  return c;
}

Color ImageMap::lookupPixel(double x, double y) const {
  Color c;
  impl_->sampler->lookup(static_cast<float>(x / impl_->linear.width),
                         static_cast<float>(y / impl_->linear.height), &c[0]);
  return c;
}

namespace {

// An image texture's pixels (decoded to linear, by the image's own gamma where it names one,
// then encoded with the working gamma; their colours divided by their alpha where the
// texture reads its transparency), from the cache when there is one.
std::shared_ptr<const ImageMap> loadImage(const ImageTexture& image, ImageMapCache* cache,
                                          const WorkingGamma& gamma) {
  // A file stored in the working gamma's own curve (POV-Ray's 3.6 gamma mode, its PPMs):
  // its values are working values as they are, read without decoding and encoding again.
  const bool stored = image.fileGamma && *image.fileGamma == gamma && !image.alphaTransmit;
  const PixelDecoding decoding = stored                ? PixelDecoding::AsStored
                                 : image.alphaTransmit ? PixelDecoding::StraightLinear
                                                       : PixelDecoding::Linear;
  std::shared_ptr<const ImageMap> map;
  try {
    map = cache ? cache->get(image.path, decoding, image.fileGamma)
                : std::make_shared<const ImageMap>(image.path, decoding, image.fileGamma);
  } catch (const ImageIOError& e) {
    throw LocatedError(image.loc, e.what(), LocatedError::Kind::Input);
  }
  if (stored || gamma.linear()) return map;
  Image working = map->pixels();  // the cache keeps the linear pixels for other scenes
  linearToWorking(gamma, working);
  return std::make_shared<const ImageMap>(std::move(working));
}

}  // namespace

TextureSet::TextureSet(const std::vector<const Material*>& surfaces, ImageMapCache* cache,
                       const WorkingGamma& gamma) {
  maps_.resize(surfaces.size());
  std::map<std::string, std::shared_ptr<const ImageMap>> byPath;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const auto* image = std::get_if<ImageTexture>(&surfaces[i]->texture);
    if (!image) continue;
    auto& map = byPath[imageKey(*image)];
    if (!map) map = loadImage(*image, cache, gamma);
    maps_[i] = map;
  }
  // The images among the entries of maps and lists, by file.
  for (const Material* m : surfaces)
    forEachImageInMaps(m->texture, [&](const ImageTexture& image) {
      auto& map = byPath[imageKey(image)];
      if (!map) map = loadImage(image, cache, gamma);
      nested_[imageKey(image)] = map;
    });
  bumpMaps_.resize(surfaces.size());
  std::map<std::string, std::shared_ptr<const ImageMap>> bumpsByPath;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const auto& bump = surfaces[i]->bumpMap;
    if (!bump) continue;
    auto& map = bumpsByPath[bump->path];
    if (!map) {
      try {
        map = cache ? cache->get(bump->path, PixelDecoding::AsStored)
                    : std::make_shared<const ImageMap>(bump->path, PixelDecoding::AsStored);
      } catch (const ImageIOError& e) {
        throw LocatedError(bump->loc, e.what(), LocatedError::Kind::Input);
      }
    }
    bumpMaps_[i] = map;
  }
}

void checkImageTextures(const std::vector<Material>& scene) {
  std::vector<const Material*> materials;
  for (const Material& m : scene) {
    materials.push_back(&m);
    for (const Material& layer : m.layers) materials.push_back(&layer);
  }
  std::set<std::string> checked;
  auto check = [&](const ImageTexture& image) {
    if (!checked.insert(image.path).second) return;
    try {
      checkImageFile(image.path);
    } catch (const ImageIOError& e) {
      throw LocatedError(image.loc, e.what(), LocatedError::Kind::Input);
    }
  };
  for (const Material* m : materials) {
    if (const auto* image = std::get_if<ImageTexture>(&m->texture)) check(*image);
    forEachImageInMaps(m->texture, check);
  }
  for (const Material* m : materials) {
    if (!m->bumpMap || !checked.insert(m->bumpMap->path).second) continue;
    try {
      checkImageFile(m->bumpMap->path);
    } catch (const ImageIOError& e) {
      throw LocatedError(m->bumpMap->loc, e.what(), LocatedError::Kind::Input);
    }
  }
}

namespace {

// The world error bound of the hit point carried back into object space (|M^-1| applied
// to it).

// An error bound carried through a linear map: |m| applied to it.
Vec3 errorThrough(const Mat4& m, const Vec3& err) {
  Vec3 out(0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[r] += std::abs(m[c][r]) * err[c];
  return out;
}

// The error bound carried into a placement's pattern space (through its transforms; the
// other warps are taken as leaving it as it is).
Vec3 placedError(const PatternPlacement& place, const Vec3& err) {
  if (place.warps.empty()) return errorThrough(place.patternFromObject, err);
  return errorThrough(linearPatternFromObject(place), err);
}

// The checker's cell (0: color1's) at an object point with its error bound.
int checkerCell(const CheckerTexture& checker, const Vec3& pObject, const Vec3& err) {
  const PatternPlacement& place = checker.placement;
  if (place.patternFromObject == Mat4(1.0) && place.turbulence == Vec3(0.0) && place.warps.empty())
    return checkerIndex(checker, pObject, err);
  // Placed: the point and its error bound carried into pattern space (turbulence moves
  // the point by a smooth displacement, which leaves the bound as it is).
  return checkerIndex(checker, warpPoint(place, pObject), placedError(place, err));
}

// A projected image's colour at the object (or map's) point p. Off a `once` image the
// surface is clear, as POV-Ray's.
PigmentColor projectedImageColour(const ImageMap& map, const ImageTexture& image, const Vec3& p) {
  const std::optional<Vec2> xy = projectToImage(image.projection, warpPoint(image.placement, p),
                                                map.width(), map.height(), image.once);
  if (!xy) return {Color(1.0f), {0.0f, 1.0f}};
  return sampleImageTexture(map.pixels(), image, *xy);
}

// (u, v, 0) is exact: no rounding error to carry.
const Vec3 kNoError(0.0);

// The colour, filter and transmit of each kind of texture at an object point. A map or a
// list of textures evaluates its entries at its own pattern-space point (POV-Ray hands
// them the warped point), so their placements compose with it.
struct PigmentAt {
  const Vec3& p;
  const Vec3& err;
  const NestedImages* images;  // the pixels of the images among the entries
  const Vec3* uv = nullptr;    // the surface's (u, v, 0), where there is a surface

  // An entry of a map or a list at the pattern-space point q (error bound qErr); a
  // uv-mapped entry at the surface's (u, v, 0) instead (POV-Ray's uv_mapping pigment reads
  // the intersection's (u, v), whatever point its map hands it).
  PigmentColor entry(const TextureMapEntry& e, const Vec3& q, const Vec3& qErr) const {
    if (std::holds_alternative<std::monostate>(e.texture)) return e.color;
    if (uv && textureUvMapped(e.texture))
      return std::visit(PigmentAt{*uv, kNoError, images, uv}, e.texture);
    return std::visit(PigmentAt{q, qErr, images, uv}, e.texture);
  }
  PigmentColor inside(const std::vector<TextureMapEntry>& entries, size_t i,
                      const PatternPlacement& place) const {
    return entry(entries[i], warpPoint(place, p), placedError(place, err));
  }

  PigmentColor operator()(std::monostate) const { return {}; }
  // An entry's image: projected from the point its map hands it, through its own placement.
  PigmentColor operator()(const ImageTexture& image) const {
    const auto found = images ? images->find(imageKey(image)) : NestedImages::const_iterator();
    if (!images || found == images->end())
      throw std::logic_error("an image texture without its pixels (not an entry of a material)");
    return projectedImageColour(*found->second, image, p);
  }
  PigmentColor operator()(const CheckerTexture& checker) const {
    const int cell = checkerCell(checker, p, err);
    if (!checker.pigments.empty()) {
      // The cells' scale is POV-Ray's `scale` of the whole pigment: it scales the
      // entries' point too.
      const PatternPlacement& place = checker.placement;
      return entry(checker.pigments[cell], warpPoint(place, p) / checker.scale,
                   placedError(place, err) / checker.scale);
    }
    return cell == 0 ? PigmentColor{checker.color1, checker.ft1}
                     : PigmentColor{checker.color2, checker.ft2};
  }
  PigmentColor operator()(const PatternTexture& pattern) const {
    if (pattern.pigments.empty())
      return lookupColorMapFT(pattern.map, patternValue(pattern.pattern, p));
    // The pigment map: the entries around the value, each at the pattern's point.
    const PatternSpec& spec = pattern.pattern;
    const Vec3 q = warpPoint(spec.placement, p, turbulenceDisplaces(spec.type));
    const Vec3 qErr = placedError(spec.placement, err);
    const std::vector<TextureMapEntry>& e = pattern.pigments;
    const MapSpan s = mapSpanAt(e.data(), e.size(), patternValueAt(spec, q));
    if (s.a == s.b) return entry(e[s.a], q, qErr);
    return blendPigments(entry(e[s.a], q, qErr), entry(e[s.b], q, qErr), s.fraction);
  }
  PigmentColor operator()(const HexagonTexture& hexagon) const {
    const int i = hexagonIndex(warpPoint(hexagon.placement, p));
    if (!hexagon.pigments.empty()) return inside(hexagon.pigments, i, hexagon.placement);
    return {hexagon.spec.colors[i], hexagon.spec.ft[i]};
  }
  PigmentColor operator()(const BrickTexture& brick) const {
    const BrickSpec& b = brick.spec;
    const int i = brickIndex(b, warpPoint(brick.placement, p));
    if (!brick.pigments.empty()) return inside(brick.pigments, i, brick.placement);
    return i == 0 ? PigmentColor{b.color1, b.ft1} : PigmentColor{b.color2, b.ft2};
  }
  PigmentColor operator()(const AverageTexture& average) const {
    // POV-Ray sums weight·colour in single precision and divides by the weights' sum.
    const Vec3 q = warpPoint(average.placement, p);
    const Vec3 qErr = placedError(average.placement, err);
    PigmentColor sum{Color(0.0f), {}};
    float total = 0.0f;
    for (const TextureMapEntry& e : average.entries) {
      const float w = static_cast<float>(e.at);
      const PigmentColor c = entry(e, q, qErr);
      sum.rgb += w * c.rgb;
      sum.ft.filter += w * c.ft.filter;
      sum.ft.transmit += w * c.ft.transmit;
      total += w;
    }
    return {sum.rgb / total, {sum.ft.filter / total, sum.ft.transmit / total}};
  }
};

// The colour of each kind of texture at a surface point: std::visit needs every kind.
Vec3 objectError(const SurfaceInfo& surface, const Instance& leaf) {
  return errorThrough(leaf.transform().objectFromWorld(), surface.pError);
}

// An <image>'s colour at a hit: at the shape's (u,v) (a shape without them reads (0,0)), or
// projected from pattern space. Off a `once` image the surface is clear, as POV-Ray's.
PigmentColor imageColour(const ImageMap& map, const ImageTexture& image,
                         const SurfaceInfo& surface) {
  const Vec2 uv = surface.hasUV ? surface.uv : Vec2(0.0);
  if (image.plainUV()) return {map.lookup(uv, image.scale), {}};
  if (image.projection != ImageProjection::uv)
    return projectedImageColour(map, image, surface.pObject);
  const std::optional<Vec2> xy = uvToImage(uv, image.scale, map.width(), map.height(), image.once);
  if (!xy) return {Color(1.0f), {0.0f, 1.0f}};
  return sampleImageTexture(map.pixels(), image, *xy);
}

struct TextureColour {
  const std::shared_ptr<const ImageMap>& map;
  const SurfaceInfo& surface;
  const Instance& leaf;
  const NestedImages& images;

  Color operator()(std::monostate) const { return Color(1.0f); }
  // A map or a list of textures: its entries' colours (their filter and transmit unused).
  // Evaluated on the material's texture itself (a copy of the variant would copy every
  // entry, per hit).
  template <class Kind>
  Color nested(const Kind& texture) const {
    const Vec3 uv = uvPointOf(surface);
    return PigmentAt{surface.pObject, objectError(surface, leaf), &images, &uv}(texture).rgb;
  }

  Color operator()(const CheckerTexture& checker) const {
    if (!checker.pigments.empty()) return nested(checker);
    return checkerCell(checker, surface.pObject, objectError(surface, leaf)) == 0 ? checker.color1
                                                                                  : checker.color2;
  }
  Color operator()(const ImageTexture& image) const {
    return imageColour(*map, image, surface).rgb;
  }
  Color operator()(const PatternTexture& pattern) const {
    if (!pattern.pigments.empty()) return nested(pattern);
    return lookupColorMap(pattern.map, patternValue(pattern.pattern, surface.pObject));
  }
  Color operator()(const HexagonTexture& hexagon) const {
    if (!hexagon.pigments.empty()) return nested(hexagon);
    return hexagonColor(hexagon.spec, warpPoint(hexagon.placement, surface.pObject));
  }
  Color operator()(const BrickTexture& brick) const {
    if (!brick.pigments.empty()) return nested(brick);
    return brickColor(brick.spec, warpPoint(brick.placement, surface.pObject));
  }
  Color operator()(const AverageTexture& average) const { return nested(average); }
};

}  // namespace

double mapValueAt(const Texture& pattern, const SurfaceInfo& hit, const Instance& leaf) {
  SurfaceInfo uvView;
  const PatternPlacement* place = texturePlacement(pattern);
  const SurfaceInfo& surface = place ? surfaceFor(*place, hit, uvView) : hit;
  const Vec3& p = surface.pObject;
  if (const auto* t = std::get_if<PatternTexture>(&pattern)) return patternValue(t->pattern, p);
  if (const auto* c = std::get_if<CheckerTexture>(&pattern))
    return checkerCell(*c, p, objectError(surface, leaf));
  if (const auto* h = std::get_if<HexagonTexture>(&pattern))
    return hexagonIndex(warpPoint(h->placement, p));
  if (const auto* b = std::get_if<BrickTexture>(&pattern))
    return brickIndex(b->spec, warpPoint(b->placement, p));
  return 0.0;
}

MapBlend mapChoice(const Material& m, const SurfaceInfo& hit, const Instance& leaf) {
  const ImagePattern* image = mapIndexImage(m);
  if (!image) return mapBlend(m.mapEntries, mapValueAt(m.mapPattern, hit, leaf));
  if (!image->values) return mapIndexEntry(0, m.mapEntries.size());  // an invalid scene's
  const PatternSpec& spec = std::get<PatternTexture>(m.mapPattern).pattern;
  SurfaceInfo uvView;
  const SurfaceInfo& surface = surfaceFor(spec.placement, hit, uvView);
  const Vec3 p = warpPoint(spec.placement, surface.pObject, turbulenceDisplaces(spec.type));
  const ImageValueGrid& grid = *image->values;
  const auto xy = projectToImage(image->projection, p, grid.width, grid.height, image->once);
  // Off a `once` image (or where the projection gives no point) POV-Ray takes number 0.
  const int number = xy ? sampleImageIndex(grid, *xy, image->interpolation, image->once) : 0;
  return mapIndexEntry(number, m.mapEntries.size());
}

PigmentColor pigmentAt(const Texture& texture, const Vec3& pObject, const Vec3& pError,
                       const NestedImages* images, const Vec3* uvPoint) {
  return std::visit(PigmentAt{pObject, pError, images, uvPoint}, texture);
}

PigmentColor TextureSet::evalPigment(uint32_t index, const Material& material,
                                     const SurfaceInfo& hit, const Instance& leaf) const {
  SurfaceInfo uvView;
  const SurfaceInfo& surface =
      textureUvMapped(material.texture) ? uvView = uvMappedSurface(hit) : hit;
  if (const auto* image = std::get_if<ImageTexture>(&material.texture))
    return imageColour(*maps_[index], *image, surface);
  const Vec3 uv = uvPointOf(hit);
  return pigmentAt(material.texture, surface.pObject, objectError(surface, leaf), &nested_, &uv);
}

Color TextureSet::eval(uint32_t index, const Material& material, const SurfaceInfo& hit,
                       const Instance& leaf) const {
  SurfaceInfo uvView;
  const SurfaceInfo& surface =
      textureUvMapped(material.texture) ? uvView = uvMappedSurface(hit) : hit;
  return std::visit(TextureColour{maps_[index], surface, leaf, nested_}, material.texture);
}

}  // namespace lucent
