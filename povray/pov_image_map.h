// Image textures as POV-Ray image_map pigments. Lucent looks an image up bilinearly at the
// shape's (u, v), repeating, v = 0 at the bottom row (render/texture.h); POV-Ray's
// `interpolate 2` is the same bilinear filter with pixel centres at (i + ½)/width and the
// same repetition (backend/support/imageutil.cpp: map_pos, Interp). What differs is how
// each maps a surface point to (u, v), so only shapes whose (u, v) a texture transform can
// reproduce are exported; each shape's registry entry (scenegraph/shapes/) says how:
//   Planar        a planar image_map, turned by the entry's uvFromObject (plane, disc, and
//                 each face of a box, written as the intersection of its face planes)
//   Spherical     map_type 1, reflected so POV-Ray's longitude and latitude equal Lucent's
//                 u = (atan2(x, z) + π)/2π and v = acos(y/r)/π; scale 1 only (sphere)
//   MeshUV        uv_mapping with the mesh's own uv_vectors
// Other shapes are errors that name the shape.
#pragma once

#include "pov_writer.h"

#include "scenegraph/material.h"
#include "scenegraph/shape_type.h"

#include <string>
#include <vector>

namespace lucent {

// The POV-Ray keyword for an image file's format ("png", "jpeg", ...), or "" if POV-Ray
// cannot read it.
std::string povImageFormat(const std::string& path);

// Writes `pigment { image_map {...} <mapping> }`; errors and warnings name `materialName`
// and `shapeName` at `loc`.
void writeImagePigment(const ImageTexture& image, double filter, double transmit,
                       const ImageMapping& mapping, const char* shapeName, const SourceLoc& loc,
                       const std::string& materialName, PovWriter& out, PovIssues& issues);

// Writes `pigment { image_map {... map_type N} <placement> }` for a projected <image>
// (projection other than uv): POV-Ray's own projection, so any shape can wear it.
void writeProjectedImagePigment(const ImageTexture& image, double filter, double transmit,
                                const std::string& materialName, PovWriter& out, PovIssues& issues);

// An image inside a map or a list of pigments, as POV-Ray takes it: readable and projected
// (errors name `materialName`); false with an error otherwise.
bool checkNestedImage(const ImageTexture& image, const std::string& materialName,
                      PovIssues& issues);
// Writes the entry's body `image_map {... map_type N} <placement>` (checked first).
void writeNestedImageBody(const ImageTexture& image, double filter, double transmit,
                          PovWriter& out);

// Writes `normal { bump_map {... map_type N} bump_size d <placement> }` for a projected
// <bump-map>: POV-Ray's own projection and bend, on any shape.
void writeProjectedBumpMapNormal(const BumpMapSpec& bump, const std::string& materialName,
                                 PovWriter& out, PovIssues& issues);

// Writes `normal { uv_mapping bump_map {...} bump_size d }` for a <bump-map>: POV-Ray's
// uv-mapped normal reads the image at the shape's (u, v) with the world normal, as Lucent
// does (render/bump_map.h), but POV-Ray has such (u, v) equal to Lucent's only for meshes
// with uvs (MeshUV) and, turned about y in the pattern's space, for spheres (Spherical);
// planes and discs have no (u, v) in POV-Ray, a box's are laid out differently, and a
// planar image_map's normal would build its frame in the pattern's space instead, so every
// other shape is an error that names it. The image is
// read without gamma (`gamma 1.0`: the stored values, as Lucent), bilinearly
// (`interpolate 2`), its grey level from the colour (`use_color`).
void writeBumpMapNormal(const BumpMapSpec& bump, const ImageMapping& mapping, const char* shapeName,
                        const SourceLoc& loc, const std::string& materialName, PovWriter& out,
                        PovIssues& issues);

}  // namespace lucent
