// Projected image maps, as POV-Ray 3.7's image_map finds and blends its pixels
// (backend/support/imageutil.cpp: map_pos, the four mappers, Interp and its filters; read as
// facts). Used by render/texture.cpp for every <image> but the plain (u,v) one, which keeps
// OpenImageIO's bilinear filter.
#pragma once

#include "image.h"

#include "images/image_values_file.h"
#include "scenegraph/texture_spec.h"

#include <optional>

namespace lucent {

// Where a pattern-space point falls on a width × height image: x across from the left
// edge and y down from the top row, in pixels, inside [0, width) × [0, height). Nothing
// where POV-Ray's image_map has no colour there: off a `once` image, or at a point its
// projection leaves undefined (the centre of the spherical and cylindrical projections,
// the axis of the torus). Planar: the image's [0,1]² lies on the square x, y ∈ [0,1] of
// the plane z = 0 (its bottom-left corner at the origin); spherical: longitude from +x
// towards +z, latitude up +y; cylindrical: the longitude, and y ∈ [0,1] up the image;
// torus: round a torus of major radius 1 about y, and round its tube.
std::optional<Vec2> projectToImage(ImageProjection projection, const Vec3& q, int width, int height,
                                   bool once);

// The same for (u,v) coordinates (u across, v up, one copy of the image over scale).
std::optional<Vec2> uvToImage(const Vec2& uv, const Vec2& scale, int width, int height, bool once);

// The colour at image point `xy` (from projectToImage), blended as POV-Ray's interpolate
// does: none takes the pixel under the point; bilinear and normalized blend the four
// nearest pixel centres, weighted by area or by inverse squared distance; bicubic the 16
// nearest with Catmull-Rom weights. Neighbours past an edge wrap round, or for a `once`
// image repeat the edge pixel. `all` is added to every pixel's filter and transmit.
PigmentColor sampleImage(const Image& image, const Vec2& xy, ImageInterpolation interpolation,
                         bool once, const FilterTransmit& all);

// An <image>'s colour at image point `xy`: sampleImage's, with a palette image's entries' own
// filter and transmit (ImageTexture::palette) blended as its colours are, as POV-Ray 3.7
// blends the RGBFT entries of a colour-mapped image.
PigmentColor sampleImageTexture(const Image& pixels, const ImageTexture& image, const Vec2& xy);

// The same blend of an image_pattern's values (no filter or transmit).
float sampleImageValue(const ImageValueGrid& grid, const Vec2& xy, ImageInterpolation interpolation,
                       bool once);

// POV-Ray 3.7's material number at image point `xy` (imageutil.cpp, material_map, as facts):
// the palette indices blended as the colours are (none: the pixel's; the blend in double
// precision) and truncated toward zero; where that gives -1 (an image without a palette
// counts -1 a pixel), the blended red channel, in single precision, times 255, truncated.
int sampleImageIndex(const ImageValueGrid& grid, const Vec2& xy, ImageInterpolation interpolation,
                     bool once);

// The palette indices alone, blended and truncated as above: -1 for an image without one.
int samplePaletteIndex(const ImageValueGrid& grid, const Vec2& xy, ImageInterpolation interpolation,
                       bool once);

}  // namespace lucent
