// <height-field src="image" smooth="false" water-level="0"/>: POV-Ray 3.7's height_field
// (primitives/height_field.h), its image read as POV-Ray reads it (images/height_map_file.h).
// The image is read while the scene is parsed, so a missing or damaged file is an error at
// the attribute; only the formats POV-Ray reads as height fields are taken. Or
// <height-field function="..." resolution="W H">: POV-Ray's `function W, H { }`, the
// function sampled on the grid as POV-Ray samples it (primitives/height_map_function.h).
#include "scenegraph/shape_type.h"

#include "scenegraph/pigment_function.h"

#include "primitives/height_field.h"
#include "primitives/height_map_function.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace lucent {

namespace {

// POV-Ray's keyword for the file's format, "" for one it does not read as a height field.
std::string povFormat(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return "png";
  if (ext == ".pgm") return "pgm";
  if (ext == ".ppm") return "ppm";
  if (ext == ".tga") return "tga";
  if (ext == ".jpg" || ext == ".jpeg") return "jpeg";
  if (ext == ".tif" || ext == ".tiff") return "tiff";
  if (ext == ".gif") return "gif";
  if (ext == ".pot") return "pot";
  return "";
}

std::string povQuoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The grid's highest point against the water level (both sources).
void checkHeights(const HeightFieldSpec& s, AttributeInput& in, const char* attr,
                  const std::string& allZero) {
  const uint16_t top = *std::max_element(s.map->values.begin(), s.map->values.end());
  if (top == 0) {
    in.attrError(attr, allZero + ": there is no field above the water level");
    return;
  }
  if (!(top / 65536.0 > s.waterLevel))
    in.attrError(
        "water-level",
        fmt::format("{} is at or above the field's highest point ({}): nothing would be left",
                    attributeText(s.waterLevel), attributeText(top / 65536.0)));
}

// function="..." resolution="W H": the function compiled and sampled now, so that a field
// of zeros is an error where it is written.
void readFunctionField(HeightFieldSpec& s, AttributeInput& in) {
  if (in.has("src")) {
    in.attrError("function", "a height field has either 'src' (an image) or 'function', not both");
    return;
  }
  if (!in.has("resolution")) {
    in.error(
        "<height-field function> needs 'resolution' (the grid's points along x and z, e.g. "
        "\"256 256\")");
    return;
  }
  const auto res = in.integers("resolution");
  if (!res) return;
  if (res->size() != 2 || (*res)[0] < 2 || (*res)[1] < 2 || (*res)[0] > kMaxFunctionFieldSide ||
      (*res)[1] > kMaxFunctionFieldSide) {
    in.attrError("resolution", fmt::format("two whole numbers from 2 to {} are expected (the "
                                           "grid's points along x and z)",
                                           kMaxFunctionFieldSide));
    return;
  }
  s.resolution[0] = static_cast<int>((*res)[0]);
  s.resolution[1] = static_cast<int>((*res)[1]);
  const auto f = in.function("function", {"x", "y", "z"});
  if (!f) return;
  s.function = f->text;
  s.constants = f->constants;
  s.field = f->field;
  s.pigments = f->pigments;
  s.map = sampleHeightMap(*s.field, s.resolution[0], s.resolution[1]);
  checkHeights(s, in, "function", "the function's value makes every height 0");
}

void readHeightField(HeightFieldSpec& s, AttributeInput& in) {
  if (in.has("function")) {
    readFunctionField(s, in);
    return;
  }
  if (in.has("resolution"))
    in.attrError("resolution", "'resolution' belongs to a height field of a 'function'");
  if (!in.has("src")) {
    in.error(
        "<height-field> needs 'src' (a grey or colour image whose brightness is the height) "
        "or 'function' (a function of x and y sampled on a grid)");
    return;
  }
  auto src = in.text("src");
  if (!src) return;
  s.src = *src;
  if (povFormat(*src).empty()) {
    in.attrError("src", "'" + *src +
                            "' is not a PNG, PGM, PPM, TGA, JPEG, TIFF, GIF or POT file, the "
                            "formats POV-Ray reads as height fields");
    return;
  }
  s.map = in.heightMapFile("src", s.path);
  if (!s.map) return;
  checkHeights(s, in, "src", "'" + *src + "' is black everywhere (every height is 0)");
}

std::shared_ptr<const Shape> buildHeightField(const HeightFieldSpec& s) {
  if (!s.map) throw std::invalid_argument("makeShape: <height-field> has no image");
  return std::make_shared<HeightField>(s.map, s.smooth, s.waterLevel, s.open);
}

void writeHeightField(const HeightFieldSpec& s, PovShapeOut& out) {
  if (!s.function.empty()) {
    std::string problem;
    const std::optional<std::string> body =
        out.function(s.function, s.constants, s.pigments, problem);
    if (!body) {
      out.error("<height-field> function: " + problem);
      return;
    }
    out.open("height_field");
    out.line(fmt::format("function {}, {} {{ {} }}", s.resolution[0], s.resolution[1], *body));
    if (s.smooth) out.line("smooth");
    if (s.waterLevel != 0.0) out.line("water_level " + out.number(s.waterLevel));
    return;
  }
  out.open("height_field");
  const std::string absolute = std::filesystem::absolute(s.path).lexically_normal().string();
  out.line(povFormat(s.path) + " " + povQuoted(absolute));
  if (s.smooth) out.line("smooth");
  if (s.waterLevel != 0.0) out.line("water_level " + out.number(s.waterLevel));
}

// A 3 x 3 grid (a ridge along z with one raised corner) and a 5 x 4 one of varied heights.
std::shared_ptr<const HeightMap> sampleMap(int w, int d, uint16_t (*f)(int, int)) {
  auto m = std::make_shared<HeightMap>();
  m->width = w;
  m->depth = d;
  for (int z = 0; z < d; ++z)
    for (int x = 0; x < w; ++x) m->values.push_back(f(x, z));
  return m;
}

}  // namespace

template <>
ShapeEntry<HeightFieldSpec> shapeEntry<HeightFieldSpec>() {
  ShapeEntry<HeightFieldSpec> e("height-field", "height fields", buildHeightField,
                                writeHeightField);
  e.doc =
      "POV-Ray's height_field: an image's brightness as heights over x, z in [0, 1], closed by "
      "walls and a floor at the water level (solid; open: the surface alone, as POV-Ray's).";
  e.children = {pigmentFunctionChild()};
  Field<HeightFieldSpec> resolution =
      readByEntry<HeightFieldSpec>("resolution", AttrType::IntegerList)
          .doc("With function: the grid's points along x and z (2 to 4096 each).");
  resolution.info.schemaType = "integerPair";
  e.fields = {readByEntry<HeightFieldSpec>("src", AttrType::File)
                  .doc("A grey or colour PNG, PGM, PPM, TGA, JPEG or TIFF image, or a GIF, "
                       "relative to the scene file, read as POV-Ray reads it: grey values are "
                       "heights; in an 8-bit colour image red is the high byte and green the low "
                       "byte, in a 16-bit one the brightness is the height; in a palette image "
                       "(a palette PNG, a GIF) the palette index times 256; a POT file (a GIF "
                       "named .pot, twice as wide) holds the high byte in its left half and the "
                       "low byte in its right. The image's top row is at z = 1."),
              readByEntry<HeightFieldSpec>("function", AttrType::Text)
                  .doc("Instead of src: an expression in x, y and z (as an isosurface's) whose "
                       "value is the height at the grid point (x, z) taken at (x, 1 - z, 0), "
                       "stored in 16 bits as POV-Ray's height_field { function W, H { } } "
                       "(outside [0, 1] it wraps around)."),
              std::move(resolution),
              booleanField("smooth", &HeightFieldSpec::smooth)
                  .doc("Interpolate POV-Ray's vertex normals over each cell."),
              numberField("water-level", &HeightFieldSpec::waterLevel,
                          NumberRule::between(0.0, 1.0, "a number from 0 to 1", false, true))
                  .doc("The height below which the field is removed (its floor)."),
              booleanField("open", &HeightFieldSpec::open)
                  .doc("Draw the surface alone, without the walls and the floor that close it, "
                       "as POV-Ray's height_field (then a surface, not a solid).")};
  e.finish = readHeightField;
  e.notSolid = [](const HeightFieldSpec& s) {
    return s.open ? std::string("it is open") : std::string();
  };
  e.triangles = [](const HeightFieldSpec& s) {
    return s.map ? 2LL * (s.map->width - 1) * (s.map->depth - 1) : 0LL;
  };
  e.samples = [] {
    HeightFieldSpec ridge;
    ridge.src = ridge.path = "ridge.png";  // not read: the samples hold their grids
    ridge.map = sampleMap(3, 3, [](int x, int z) -> uint16_t {
      return x == 1 ? 40000 : (x == 2 && z == 2 ? 60000 : 10000);
    });
    HeightFieldSpec varied;
    varied.src = varied.path = "varied.png";
    varied.map = sampleMap(5, 4, [](int x, int z) -> uint16_t {
      return static_cast<uint16_t>(((x * 7 + z * 13) % 11) * 5000 + 3000);
    });
    HeightFieldSpec smooth = varied;
    smooth.smooth = true;
    HeightFieldSpec water = varied;
    water.waterLevel = 0.4;
    HeightFieldSpec open = water;
    open.open = true;
    return std::vector<std::pair<std::string, HeightFieldSpec>>{
        {"3 x 3 height field", ridge},
        {"5 x 4 height field", varied},
        {"smooth height field", smooth},
        {"height field with a water level", water},
        {"open height field", open}};
  };
  return e;
}

}  // namespace lucent
