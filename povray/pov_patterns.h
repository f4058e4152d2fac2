// The contract's patterns as POV-Ray 3.7 pigments and normals: the pattern keyword with its
// own modifiers, a color_map (always written: without one Lucent's value is the grey
// level, POV-Ray's default map is not), then turbulence and the pattern's transform in that
// order (POV-Ray applies a transform written after a warp to the point before the warp, so
// the turbulence works in pattern space, as in Lucent).
#pragma once

#include "pov_writer.h"

#include "scenegraph/image_pattern.h"
#include "scenegraph/material.h"
#include "scenegraph/object_pattern.h"
#include "scenegraph/pigment_function.h"

#include <memory>
#include <vector>

namespace lucent {

// `scale` multiplies every colour (the diffuse colour the pigment carries); filter and
// transmit are written into each colour, plus the colour's own (FilterTransmit).
void writePatternPigment(const PatternTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out);
void writeCheckerPigment(const CheckerTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out);
void writeHexagonPigment(const HexagonTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out);
// `average pigment_map { [weight P] ... }`; maps and lists of pigments are written by
// each kind's writer (pigment_map, `checker pigment {..} pigment {..}`).
void writeAveragePigment(const AverageTexture& t, const Vec3& scale, double filter, double transmit,
                         PovWriter& out);
void writeBrickPigment(const BrickTexture& t, const Vec3& scale, double filter, double transmit,
                       PovWriter& out);
// `normal { PATTERN depth ... }`.
void writeNormal(const NormalSpec& n, PovWriter& out);
// The pattern keyword with its arguments ("gradient <0, 1, 0>"), and the value's modifiers
// (frequency, phase, wave), for a pattern written without its colours (a texture_map's).
std::string patternKeyword(const PatternSpec& s);
// The pattern keyword on its line, then `after` (a normal's depth); pigment_pattern's is a
// block holding its pigment's body.
void writePatternKeyword(const PatternSpec& s, PovWriter& out, const std::string& after = {});
// `#declare NAME = function { pigment { ... } }` for each pigment a function calls, written
// before the pattern or the isosurface whose function calls them (POV-Ray's directives may
// stand inside a block).
void writePigmentFunctions(const std::vector<std::shared_ptr<const PigmentFunction>>& pigments,
                           PovWriter& out);
void writePigmentFunctions(const PatternSpec& s, PovWriter& out);
void writeValueModifiers(const PatternSpec& s, PovWriter& out);
// An image-pattern's file and reading: `FORMAT "file" map_type N once interpolate N` (what
// image_pattern and material_map share; POV-Ray reads both files without gamma correction).
std::string imageReadingSpec(const ImagePattern& im);
// A pattern's turbulence and transform (after the pattern's own modifiers).
void writePlacement(const PatternPlacement& p, PovWriter& out);
// `uv_mapping` for a uv-mapped placement (the first line of its pigment or normal block).
void writeUvMapping(const PatternPlacement& p, PovWriter& out);

// The object pattern's declared object (`#declare NAME = ...`, written by the exporter
// before the materials): "LucentObject_" and the node's id, its other characters as '_'.
std::string povObjectPatternName(const ObjectPattern& o);
// An object pattern's value is 0 or 1 only (no frequency and a ramp wave), so that POV-Ray's
// list of two, at 0 and 1, can stand for any map: the first entry and the last.
bool objectPatternTwoValued(const PatternSpec& s);

}  // namespace lucent
