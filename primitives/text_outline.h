// A string's glyph outlines, laid out as POV-Ray 3.7's text object lays them out, read with
// FreeType (the only file that uses it). Facts from POV-Ray's source/core/shape/truetype.cpp:
// font units are divided by the font's units per em (the em is 1 unit), unhinted; the
// baseline is y = 0; the first glyph is moved so that its leftmost point is at x = 0 and
// the pen then stands at its advance minus its left side bearing; every later glyph is drawn
// at the pen plus its left side bearing minus its leftmost point plus the pair kerning of
// the font's 'kern' table (FreeType's FT_Get_Kerning, no less than −1 em), and the pen moves
// by its advance plus that kerning; after each glyph the pen moves by `offset` too.
#pragma once

#include "prism_outline.h"

#include <string>
#include <vector>

namespace lucent {

struct PlacedGlyph {
  char32_t codepoint = 0;
  unsigned glyphIndex = 0;             // 0 (the font's missing-glyph box) when the font lacks it
  Vec2 origin{0.0};                    // where its font-unit origin went (x, y)
  double advance = 0.0;                // hmtx advance, em units
  double kerning = 0.0;                // kerning with the glyph before, em units
  std::vector<PrismContour> contours;  // x in .x, y in .y; empty for blank glyphs
};

struct TextOutline {
  std::vector<PlacedGlyph> glyphs;
  bool evenOdd = false;  // the font's own fill rule flag (TrueType: nonzero)
  std::string error;     // non-empty when the font cannot be read (then no glyphs)
};

// Decodes `utf8` (an invalid sequence is an error) and lays out its glyphs in `fontFile`.
TextOutline textOutline(const std::string& fontFile, const std::string& utf8, Vec2 offset);
// The same from the font file's bytes (the fuzz target).
TextOutline textOutlineFromBytes(const std::string& fontBytes, const std::string& utf8,
                                 Vec2 offset);

// For the tests: the number of pixels where FreeType's rasteriser, at `pixelsPerEm`, fills
// the glyph of `codepoint` differently by the even-odd and the nonzero rule (-1 on error).
long fillRuleDifference(const std::string& fontFile, char32_t codepoint, int pixelsPerEm);

// The font Lucent ships with (DejaVu Sans, Debian's fonts-dejavu-core).
const char* defaultFontFile();

}  // namespace lucent
