// FreeType turns the font file into outlines (FT_Outline_Decompose: lines, conic = quadratic
// and cubic Béziers, in font units with FT_LOAD_NO_SCALE, so unhinted); this file only
// converts them into prism contours and places them as POV-Ray's truetype.cpp does (the
// header says how). Left side bearings and advances come from the font's hmtx table, which
// is what POV-Ray reads, with FreeType's metrics for fonts that have none.
#include "text_outline.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

#include <algorithm>
#include <cstring>
#include <memory>

namespace lucent {

namespace {

// Owns the library and the face for one call.
struct FreeTypeFace {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  ~FreeTypeFace() {
    if (face) FT_Done_Face(face);
    if (lib) FT_Done_FreeType(lib);
  }
};

std::string ftError(FT_Error e) {
  switch (e) {
    case FT_Err_Cannot_Open_Resource:
      return "the file cannot be opened";
    case FT_Err_Unknown_File_Format:
      return "not a font FreeType can read (another format, or damaged or truncated)";
    case FT_Err_Invalid_File_Format:
      return "the font file is damaged";
    case FT_Err_Out_Of_Memory:
      return "out of memory";
    default:
      return "FreeType error " + std::to_string(static_cast<int>(e)) +
             " (a damaged or unsupported font)";
  }
}

// Opens the face (from the file, or from `bytes` when given) and selects a Unicode
// character map (the first map if it has none).
std::string openFace(FreeTypeFace& f, const std::string& file, const std::string* bytes = nullptr) {
  if (FT_Error e = FT_Init_FreeType(&f.lib)) return ftError(e);
  const FT_Error opened =
      bytes ? FT_New_Memory_Face(f.lib, reinterpret_cast<const FT_Byte*>(bytes->data()),
                                 static_cast<FT_Long>(bytes->size()), 0, &f.face)
            : FT_New_Face(f.lib, file.c_str(), 0, &f.face);
  if (opened) {
    f.face = nullptr;
    return ftError(opened);
  }
  if (!FT_IS_SCALABLE(f.face)) return "the font has no outlines (a bitmap font)";
  // POV-Ray refuses the same range of units per em.
  if (f.face->units_per_EM < 16 || f.face->units_per_EM > 16384)
    return "the font's units per em (" + std::to_string(f.face->units_per_EM) +
           ") is outside 16 to 16384";
  if (FT_Select_Charmap(f.face, FT_ENCODING_UNICODE) != 0) {
    if (f.face->num_charmaps == 0) return "the font has no character map";
    if (FT_Error e = FT_Set_Charmap(f.face, f.face->charmaps[0])) return ftError(e);
  }
  return {};
}

bool decodeUtf8(const std::string& s, std::vector<char32_t>& out) {
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (n < 0 || i + n >= s.size()) return false;
    char32_t cp = n == 0 ? c : (c & (0x3F >> n));
    for (int k = 1; k <= n; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + k]);
      if ((d >> 6) != 2) return false;
      cp = (cp << 6) | (d & 0x3F);
    }
    static const char32_t kMin[] = {0, 0x80, 0x800, 0x10000};
    if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    out.push_back(cp);
    i += n + 1;
  }
  return true;
}

// The hmtx table's (advance, left side bearing) of a glyph, in font units.
struct Hmtx {
  std::vector<unsigned char> bytes;
  unsigned longCount = 0;
  bool load(FT_Face face) {
    if (!FT_IS_SFNT(face)) return false;
    auto* hhea = static_cast<TT_HoriHeader*>(FT_Get_Sfnt_Table(face, FT_SFNT_HHEA));
    if (!hhea || hhea->number_Of_HMetrics == 0) return false;
    FT_ULong length = 0;
    if (FT_Load_Sfnt_Table(face, TTAG_hmtx, 0, nullptr, &length) != 0 || length < 4) return false;
    bytes.resize(length);
    if (FT_Load_Sfnt_Table(face, TTAG_hmtx, 0, bytes.data(), &length) != 0) return false;
    longCount = std::min<unsigned>(hhea->number_Of_HMetrics, static_cast<unsigned>(length / 4));
    return longCount > 0;
  }
  int u16(size_t at) const { return at + 1 < bytes.size() ? (bytes[at] << 8) | bytes[at + 1] : 0; }
  int s16(size_t at) const {
    int v = u16(at);
    return v >= 0x8000 ? v - 0x10000 : v;
  }
  // Glyphs beyond the long metrics share the last advance and have a bearing of their own.
  void metrics(unsigned glyph, int& advance, int& lsb) const {
    if (glyph < longCount) {
      advance = u16(4 * glyph);
      lsb = s16(4 * glyph + 2);
    } else {
      advance = u16(4 * (longCount - 1));
      lsb = s16(4 * longCount + 2 * (glyph - longCount));
    }
  }
};

// FT_Outline_Decompose's callbacks: font-unit points scaled to em units and moved to the
// glyph's origin; each point is computed from its integers alone, so the end of a segment
// and the start of the next are the same doubles.
struct ContourBuilder {
  double scale;
  Vec2 origin;
  std::vector<PrismContour> contours;
  Vec2 current{0.0};
  Vec2 at(const FT_Vector* v) const { return {origin.x + v->x * scale, origin.y + v->y * scale}; }
  void add(int degree, const Vec2* p) {
    PrismSegment s;
    s.degree = degree;
    s.p[0] = current;
    for (int i = 1; i <= degree; ++i) s.p[i] = p[i - 1];
    if (degree == 1 && s.p[1] == s.p[0]) return;  // the closing line of an already closed contour
    contours.back().push_back(s);
    current = s.p[degree];
  }
  static int moveTo(const FT_Vector* to, void* user) {
    auto* b = static_cast<ContourBuilder*>(user);
    if (!b->contours.empty() && b->contours.back().empty()) b->contours.pop_back();
    b->contours.emplace_back();
    b->current = b->at(to);
    return 0;
  }
  static int lineTo(const FT_Vector* to, void* user) {
    auto* b = static_cast<ContourBuilder*>(user);
    const Vec2 p[1] = {b->at(to)};
    b->add(1, p);
    return 0;
  }
  static int conicTo(const FT_Vector* c, const FT_Vector* to, void* user) {
    auto* b = static_cast<ContourBuilder*>(user);
    const Vec2 p[2] = {b->at(c), b->at(to)};
    b->add(2, p);
    return 0;
  }
  static int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto* b = static_cast<ContourBuilder*>(user);
    const Vec2 p[3] = {b->at(c1), b->at(c2), b->at(to)};
    b->add(3, p);
    return 0;
  }
};

constexpr FT_Int32 kLoadFlags =
    FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP | FT_LOAD_IGNORE_TRANSFORM;

std::string describe(char32_t cp) {
  char buf[32];
  if (cp >= 0x20 && cp < 0x7F) std::snprintf(buf, sizeof buf, "'%c'", static_cast<char>(cp));
  else std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
  return buf;
}

}  // namespace

const char* defaultFontFile() { return LUCENT_DEFAULT_FONT; }

namespace {

TextOutline layout(const std::string& fontFile, const std::string* bytes, const std::string& utf8,
                   Vec2 offset) {
  TextOutline out;
  std::vector<char32_t> cps;
  if (!decodeUtf8(utf8, cps)) {
    out.error = "the string is not valid UTF-8";
    return out;
  }
  FreeTypeFace f;
  out.error = openFace(f, fontFile, bytes);
  if (!out.error.empty()) return out;
  Hmtx hmtx;
  const bool haveHmtx = hmtx.load(f.face);
  const double unit = 1.0 / f.face->units_per_EM;
  const FT_Outline_Funcs funcs{&ContourBuilder::moveTo,
                               &ContourBuilder::lineTo,
                               &ContourBuilder::conicTo,
                               &ContourBuilder::cubicTo,
                               0,
                               0};
  Vec2 pen{0.0};
  const bool kern = FT_HAS_KERNING(f.face);
  for (size_t i = 0; i < cps.size(); ++i) {
    PlacedGlyph g;
    g.codepoint = cps[i];
    g.glyphIndex = FT_Get_Char_Index(f.face, cps[i]);
    if (FT_Error e = FT_Load_Glyph(f.face, g.glyphIndex, kLoadFlags)) {
      out.error = "the glyph of " + describe(cps[i]) + " cannot be read: " + ftError(e);
      out.glyphs.clear();
      return out;
    }
    FT_GlyphSlot slot = f.face->glyph;
    if (slot->format != FT_GLYPH_FORMAT_OUTLINE) {
      out.error = "the glyph of " + describe(cps[i]) + " is not an outline";
      out.glyphs.clear();
      return out;
    }
    FT_BBox box{0, 0, 0, 0};
    if (slot->outline.n_points > 0) FT_Outline_Get_CBox(&slot->outline, &box);
    int advance = static_cast<int>(slot->metrics.horiAdvance), lsb = static_cast<int>(box.xMin);
    if (haveHmtx) hmtx.metrics(g.glyphIndex, advance, lsb);
    g.advance = advance * unit;
    if (i == 0) {
      g.origin = Vec2(-box.xMin * unit, 0.0);
      pen.x = (advance - lsb) * unit;
    } else {
      FT_Vector k{0, 0};
      if (kern)
        FT_Get_Kerning(f.face, out.glyphs.back().glyphIndex, g.glyphIndex, FT_KERNING_UNSCALED, &k);
      const long kx = std::max<long>(k.x, -static_cast<long>(f.face->units_per_EM));
      g.kerning = kx * unit;
      g.origin = Vec2(pen.x + (lsb - box.xMin + kx) * unit, pen.y);
      pen.x += (advance + kx) * unit;
    }
    pen += offset;
    ContourBuilder b{unit, g.origin, {}, Vec2(0.0)};
    if (slot->outline.n_contours > 0) {
      if (FT_Error e = FT_Outline_Decompose(&slot->outline, &funcs, &b)) {
        out.error = "the outline of " + describe(cps[i]) + " cannot be read: " + ftError(e);
        out.glyphs.clear();
        return out;
      }
      if (!b.contours.empty() && b.contours.back().empty()) b.contours.pop_back();
      out.evenOdd = (slot->outline.flags & FT_OUTLINE_EVEN_ODD_FILL) != 0;
    }
    g.contours = std::move(b.contours);
    out.glyphs.push_back(std::move(g));
  }
  return out;
}

}  // namespace

TextOutline textOutline(const std::string& fontFile, const std::string& utf8, Vec2 offset) {
  return layout(fontFile, nullptr, utf8, offset);
}

TextOutline textOutlineFromBytes(const std::string& fontBytes, const std::string& utf8,
                                 Vec2 offset) {
  return layout({}, &fontBytes, utf8, offset);
}

long fillRuleDifference(const std::string& fontFile, char32_t codepoint, int pixelsPerEm) {
  FreeTypeFace f;
  if (!openFace(f, fontFile).empty()) return -1;
  if (FT_Set_Pixel_Sizes(f.face, 0, pixelsPerEm) != 0) return -1;
  if (FT_Load_Char(f.face, codepoint, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0) return -1;
  FT_Outline& o = f.face->glyph->outline;
  if (o.n_points == 0) return 0;
  FT_BBox box;
  FT_Outline_Get_CBox(&o, &box);
  FT_Outline_Translate(&o, -(box.xMin & ~63) + 64, -(box.yMin & ~63) + 64);
  const int w = static_cast<int>((box.xMax - (box.xMin & ~63)) / 64 + 3);
  const int h = static_cast<int>((box.yMax - (box.yMin & ~63)) / 64 + 3);
  std::vector<unsigned char> pix[2];
  for (int rule = 0; rule < 2; ++rule) {
    pix[rule].assign(static_cast<size_t>(w) * h, 0);
    FT_Bitmap bm{};
    bm.rows = h;
    bm.width = w;
    bm.pitch = w;
    bm.buffer = pix[rule].data();
    bm.num_grays = 256;
    bm.pixel_mode = FT_PIXEL_MODE_GRAY;
    if (rule) o.flags |= FT_OUTLINE_EVEN_ODD_FILL;
    else o.flags &= ~FT_OUTLINE_EVEN_ODD_FILL;
    if (FT_Outline_Get_Bitmap(f.lib, &o, &bm) != 0) return -1;
  }
  long diff = 0;
  for (size_t i = 0; i < pix[0].size(); ++i) diff += pix[0][i] != pix[1][i];
  return diff;
}

}  // namespace lucent
