// The contract's <bump-map>: POV-Ray 3.7's bump_map (imageutil.cpp, bump_map) as a
// `uv_mapping` normal applies it, read at the shape's (u,v). Only shading sees it.
#pragma once

#include "texture.h"

#include "primitives/math.h"

namespace lucent {

// POV-Ray's grey level of a colour: 0.297 R + 0.589 G + 0.114 B, stored in single
// precision as POV-Ray's colours are.
float bumpGrey(const Color& c);

// The perturbed unit normal at (u,v) for the unit normal `n` (already facing the viewer, in
// the world: POV-Ray's uv-mapped normals skip the object's transform).
//
// The image (stored values, bilinear) is read at pixel coordinates (x, y) = (u·w, (1−v)·h)
// and at (x−1, y+1) and (x+1, y+1) (one row further down the image, repeating), giving grey
// levels g1, g2, g3. The triangle p1 = (0, a·g1, 0), p2 = (−1, a·g2, 1), p3 = (1, a·g3, 1),
// with a = depth in single precision and each product rounded to single precision as
// POV-Ray's, has the unit normal b = normalize((p3 − p2) × (p1 − p2)). The frame: Y' = n,
// X' = normalize(n × (0,1,0)), Z' = normalize(X' × Y'); where |n × (0,1,0)| < 1e-10 it is
// X' = (1,0,0) with Y' = (0,1,0) (n ≈ +y) or Y' = (0,−1,0) (otherwise). The result is
// normalize(b.x·X' + b.y·Y' − b.z·Z'); a flat image leaves n as it is.
Vec3 bumpMapNormal(const ImageMap& map, double depth, const Vec2& uv, const Vec3& n);

// The same for a bump map read at image point `xy` (render/image_projection.h: x across, y
// down from the top row, in pixels) with POV-Ray's interpolation and `once` edge rule; its
// neighbours are (x − 1, y + 1) and (x + 1, y + 1), wrapped round the image as POV-Ray
// wraps them.
//
// With `indices` (a palette image read with use_index) the heights are the three points'
// palette indices themselves (a · index, 0..255 unscaled), as POV-Ray 3.7 takes them; where
// a blend gives -1 at one of them it falls back to the grey levels, as POV-Ray does.
Vec3 bumpMapNormalAt(const Image& pixels, double depth, const Vec2& xy,
                     ImageInterpolation interpolation, bool once, const Vec3& n,
                     const ImageValueGrid* indices = nullptr);

}  // namespace lucent
