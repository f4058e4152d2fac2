// <text string="..." font="file.ttf" thickness="1" offset="0 0"/>: POV-Ray 3.7's text object
// (primitives/text.h), its glyphs laid out as POV-Ray lays them out (primitives/
// text_outline.h). The font is read, through the scene's file-access rules, when the scene
// is read, so that a missing or damaged font is an error located at the attribute.
#include "scenegraph/shape_type.h"

#include "primitives/text.h"

#include <fmt/format.h>

#include <stdexcept>

namespace lucent {

namespace {

std::string fontOf(const TextSpec& s) {
  return s.fontPath.empty() ? defaultFontFile() : s.fontPath;
}

void readText(TextSpec& s, AttributeInput& in) {
  if (!in.has("string")) {
    in.error("<text> needs 'string' (the text to show)");
    return;
  }
  if (auto t = in.text("string")) s.string = *t;
  s.offset = Vec2(0.0);
  if (auto o = in.numbers("offset")) {
    if (o->size() != 2) {
      in.attrError("offset", fmt::format("expected two numbers (x y), got {}", o->size()));
      return;
    }
    s.offset = Vec2((*o)[0], (*o)[1]);
  }
  if (in.has("font")) {
    auto written = in.text("font");
    auto path = in.filePath("font");
    if (!written || !path) return;
    s.font = *written;
    s.fontPath = *path;
  }
  if (in.failed()) return;
  auto outline = std::make_shared<TextOutline>(textOutline(fontOf(s), s.string, s.offset));
  if (!outline->error.empty()) {
    if (outline->error.find("UTF-8") != std::string::npos) in.attrError("string", outline->error);
    else if (in.has("font"))
      in.attrError("font", "cannot read the font '" + s.font + "': " + outline->error);
    else
      in.error(std::string("cannot read the default font '") + defaultFontFile() +
               "': " + outline->error);
    return;
  }
  size_t drawn = 0;
  for (const PlacedGlyph& g : outline->glyphs) drawn += g.contours.empty() ? 0 : 1;
  if (drawn == 0) in.warning("<text>: the string has no visible glyph; the shape is empty");
  std::string missing;
  for (const PlacedGlyph& g : outline->glyphs)
    if (g.glyphIndex == 0 && missing.size() < 40)
      missing += fmt::format(" U+{:04X}", static_cast<unsigned>(g.codepoint));
  if (!missing.empty())
    in.warning("<text>: the font has no glyph for" + missing + "; its missing-glyph box is shown");
  s.outline = std::move(outline);
}

std::shared_ptr<const Shape> buildText(const TextSpec& s) {
  std::shared_ptr<const TextOutline> outline = s.outline;
  if (!outline) outline = std::make_shared<TextOutline>(textOutline(fontOf(s), s.string, s.offset));
  if (!outline->error.empty()) throw std::invalid_argument("makeShape: <text>: " + outline->error);
  std::vector<std::vector<PrismContour>> glyphs;
  std::vector<Vec2> blanks;
  for (const PlacedGlyph& g : outline->glyphs) {
    glyphs.push_back(g.contours);
    if (g.contours.empty()) blanks.push_back(g.origin);
  }
  return std::make_shared<Text>(glyphs, s.thickness, blanks);
}

// A POV-Ray string: quotes and backslashes escaped, other characters than printable ASCII
// as \uXXXX (POV-Ray's strings hold 16-bit characters; others become U+FFFD). POV-Ray 3.7's
// default `charset ascii` looks such codes up in the font's Macintosh Roman map first, so
// they match only with `charset utf8` (docs/scene-language.md says so).
std::string povText(const std::string& utf8) {
  std::string out = "\"";
  for (size_t i = 0; i < utf8.size();) {
    unsigned char c = static_cast<unsigned char>(utf8[i]);
    int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : 3;
    char32_t cp = n == 0 ? c : (c & (0x3F >> n));
    for (int k = 1; k <= n && i + k < utf8.size(); ++k) cp = (cp << 6) | (utf8[i + k] & 0x3F);
    i += n + 1;
    if (cp == '"' || cp == '\\') out += fmt::format("\\{}", static_cast<char>(cp));
    else if (cp >= 0x20 && cp < 0x7F) out += static_cast<char>(cp);
    else out += fmt::format("\\u{:04X}", cp > 0xFFFF ? 0xFFFDu : static_cast<unsigned>(cp));
  }
  return out + "\"";
}

void writeText(const TextSpec& s, PovShapeOut& out) {
  out.open("text");
  out.line(fmt::format("ttf {} {} {}, <{}, {}, 0>", povText(fontOf(s)), povText(s.string),
                       out.number(s.thickness), out.number(s.offset.x), out.number(s.offset.y)));
}

}  // namespace

template <>
ShapeEntry<TextSpec> shapeEntry<TextSpec>() {
  ShapeEntry<TextSpec> e("text", "texts", buildText, writeText);
  e.doc =
      "POV-Ray's text: the glyphs of a string in a TrueType or OpenType font on the xy-plane from "
      "the origin (baseline y = 0, 1 unit per em), extruded from z = 0 to z = thickness.";
  e.fields = {readByEntry<TextSpec>("string", AttrType::Text)
                  .doc("The text, UTF-8 (required; an empty string makes an empty shape)."),
              readByEntry<TextSpec>("font", AttrType::File)
                  .doc("A TrueType or OpenType font file, relative to the scene file; default: "
                       "DejaVu Sans, the font shipped with Lucent."),
              numberField("thickness", &TextSpec::thickness, NumberRule::positive())
                  .doc("The extrusion depth along z."),
              readByEntry<TextSpec>("offset", AttrType::NumberList, "0 0", {}, 2)
                  .doc("x y added to the pen after each character (POV-Ray's offset).")};
  e.finish = readText;
  e.samples = [] {
    TextSpec holes;
    holes.string = "o8e";
    TextSpec spaced;
    spaced.string = "Lu A";
    spaced.thickness = 0.25;
    spaced.offset = Vec2(0.1, -0.05);
    return std::vector<std::pair<std::string, TextSpec>>{{"text with holes", holes},
                                                         {"spaced text", spaced}};
  };
  return e;
}

}  // namespace lucent
