// Image textures as POV-Ray image_map pigments. Lucent looks an image up bilinearly at the
// shape's (u, v), repeating, v = 0 at the bottom row (render/texture.h); POV-Ray's
// `interpolate 2` is the same bilinear filter with pixel centres at (i + ½)/width and the
// same repetition (backend/support/imageutil.cpp: map_pos, Interp). What differs is how
// each maps a surface point to (u, v), so only shapes whose (u, v) a texture transform can
// reproduce are exported:
//   plane, disc   planar image_map, its x, y turned onto the tangents of planeTangents()
//   box           written as the intersection of its six face planes, each with a planar
//                 image_map placed on the face's own [0,1]² square (primitives/box.h)
//   sphere        map_type 1 (spherical), reflected so POV-Ray's longitude and latitude
//                 equal Lucent's u = (atan2(x, z) + π)/2π and v = acos(y/r)/π; scale 1 only
//   mesh          uv_mapping with the mesh's own uv_vectors
// Other shapes are errors that name the shape.
#pragma once

#include "pov_writer.h"

#include "scenegraph/material.h"
#include "scenegraph/shape_spec.h"

#include <string>
#include <vector>

namespace lucent {

// The POV-Ray keyword for an image file's format ("png", "jpeg", ...), or "" if POV-Ray
// cannot read it.
std::string povImageFormat(const std::string& path);

// How a surface point becomes the image's (u, v).
struct ImageMapping {
  enum Kind { None, Planar, Spherical, MeshUV } kind = None;
  // Planar: the affine map from the shape's object space to (u, v, w); u and v are Lucent's
  // coordinates, w anything that keeps the map invertible.
  Mat4 uvFromObject{1.0};
  Vec3 center{0.0};  // spherical: the sphere's centre
};

// The mapping of a plane, disc, sphere or mesh with uvs; None for the others (a box's
// faces each have their own: boxFaces()).
ImageMapping imageMappingFor(const ShapeSpec& shape);

// A box face as a POV-Ray plane (inside towards the box) with its (u, v) mapping.
struct BoxFace {
  Vec3 normal{0.0};
  double offset = 0.0;
  ImageMapping mapping;
};
std::vector<BoxFace> boxFaces(const BoxSpec& box);

// Writes `pigment { image_map {...} <mapping> }`; errors and warnings name `materialName`
// and `shapeName` at `loc`.
void writeImagePigment(const ImageTexture& image, double filter, double transmit,
                       const ImageMapping& mapping, const char* shapeName, const SourceLoc& loc,
                       const std::string& materialName, PovWriter& out, PovIssues& issues);

}  // namespace lucent
