// Walks a PLY file (header, then every element) without storing it, so that CGAL 5.5's PLY
// reader only ever sees files it can read safely. The rules below mirror that reader
// (CGAL/IO/PLY.h, CGAL/IO/PLY/PLY_reader.h):
// - a property of unknown type is silently dropped by CGAL, which then misreads every later
//   byte: refused;
// - a list count is used to size a buffer before anything is read, and a failed read does not
//   stop the loop: counts are checked against the data that is actually there;
// - vertex x, y, z are fetched as float or double through an unchecked cast: they must exist
//   and be float or double; likewise colour and halfedge properties CGAL fetches by type.
// Face indices are also range-checked here, to name the face in the message. Vertex normals
// and texture coordinates, which CGAL's soup reader drops, are kept on the way.
#include "mesh_error.h"
#include "mesh_file_check.h"
#include "mesh_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace lucent {
namespace {

using namespace meshtext;

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> plyType(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

std::size_t byteSize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool isReal(PlyType t) { return t == PlyType::Float32 || t == PlyType::Float64; }

void intRange(PlyType t, long long& lo, long long& hi) {
  switch (t) {
    case PlyType::Int8:
      lo = -128;
      hi = 127;
      return;
    case PlyType::UInt8:
      lo = 0;
      hi = 255;
      return;
    case PlyType::Int16:
      lo = -32768;
      hi = 32767;
      return;
    case PlyType::UInt16:
      lo = 0;
      hi = 65535;
      return;
    case PlyType::Int32:
      lo = std::numeric_limits<int32_t>::min();
      hi = std::numeric_limits<int32_t>::max();
      return;
    default:
      lo = 0;
      hi = std::numeric_limits<uint32_t>::max();
      return;
  }
}

struct PlyProperty {
  std::string name;
  std::size_t line = 0;
  bool list = false;
  PlyType countType = PlyType::UInt8;  // lists only
  PlyType type = PlyType::Float32;     // scalar type, or type of the list items
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::size_t line = 0;
  std::vector<PlyProperty> properties;

  const PlyProperty* find(std::string_view n) const {  // CGAL looks up the first of a name
    for (const PlyProperty& p : properties)
      if (p.name == n) return &p;
    return nullptr;
  }
  bool isVertex() const { return name == "vertex" || name == "vertices"; }
  bool isFace() const { return name == "face" || name == "faces"; }
};

enum class PlyEncoding { Ascii, LittleEndian, BigEndian };

[[noreturn]] void fail(const std::string& message) { throw MeshError(message); }

bool isScalarOf(const PlyProperty* p, PlyType t) { return p && !p->list && p->type == t; }

// The face list CGAL will read, chosen in CGAL's order; nullptr if none qualifies.
const PlyProperty* faceIndexList(const PlyElement& e) {
  for (const char* tag : {"vertex_indices", "vertex_index"}) {
    const PlyProperty* p = e.find(tag);
    if (p && p->list && (p->type == PlyType::Int32 || p->type == PlyType::UInt32)) return p;
  }
  return nullptr;
}

// CGAL reads colours as uchar by name once it has decided the element has colours; a
// same-named property of another type would then be cast to the wrong class.
void checkColours(const PlyElement& e) {
  auto u8 = [&](const char* n) { return isScalarOf(e.find(n), PlyType::UInt8); };
  bool hasColours = (u8("red") || u8("r")) && (u8("green") || u8("g")) && (u8("blue") || u8("b"));
  if (!hasColours) return;
  const char* tags[3] = {"r", "g", "b"};
  if (u8("red")) tags[0] = "red", tags[1] = "green", tags[2] = "blue";
  for (const char* tag : tags) {
    const PlyProperty* p = e.find(tag);
    if (p && !isScalarOf(p, PlyType::UInt8))
      fail(
          fmt::format("PLY colour property '{}' (line {}) must be uchar like the other colour "
                      "properties of '{}'",
                      tag, p->line, e.name));
  }
}

void checkElementSemantics(const std::vector<PlyElement>& elements) {
  unsigned long long vertices = 0, faces = 0;
  bool haveVertexElement = false, haveFaceElement = false;
  for (const PlyElement& e : elements) {
    // Also stops CGAL from looping over a huge count of items that have no properties.
    if (e.count > std::max(kMaxMeshVertices, kMaxMeshFaces))
      fail(fmt::format("the PLY header declares {} '{}' elements; the limit is {}", e.count, e.name,
                       std::max(kMaxMeshVertices, kMaxMeshFaces)));
    if (e.isVertex()) {
      haveVertexElement = true;
      vertices += e.count;
      for (const char* axis : {"x", "y", "z"}) {
        const PlyProperty* p = e.find(axis);
        if (!p)
          fail(
              fmt::format("PLY element '{}' (line {}) has no property '{}'", e.name, e.line, axis));
        if (p->list || !isReal(p->type))
          fail(fmt::format("PLY vertex property '{}' (line {}) must be float or double", axis,
                           p->line));
      }
      checkColours(e);
    } else if (e.isFace()) {
      haveFaceElement = true;
      faces += e.count;
      if (!faceIndexList(e))
        fail(
            fmt::format("PLY element '{}' (line {}) has no 'vertex_indices' (or 'vertex_index') "
                        "list of int or uint",
                        e.name, e.line));
      checkColours(e);
    } else if (e.name == "halfedge") {
      for (const char* tag : {"source", "target"}) {
        const PlyProperty* p = e.find(tag);
        if (p && !isScalarOf(p, PlyType::UInt32))
          fail(fmt::format("PLY halfedge property '{}' (line {}) must be uint", tag, p->line));
      }
    }
  }
  if (!haveVertexElement) fail("the PLY header declares no 'vertex' element");
  if (!haveFaceElement)
    fail("the PLY header declares no 'face' element (a point cloud has no surface)");
  if (vertices > kMaxMeshVertices)
    fail(fmt::format("the PLY header declares {} vertices; the limit is {}", vertices,
                     kMaxMeshVertices));
  if (faces > kMaxMeshFaces)
    fail(fmt::format("the PLY header declares {} faces; the limit is {}", faces, kMaxMeshFaces));
}

// Parses the header; returns the byte offset where the data starts.
std::size_t parseHeader(std::string_view bytes, PlyEncoding& encoding,
                        std::vector<PlyElement>& elements) {
  Lines lines(bytes);
  std::string_view line;
  std::vector<std::string_view> tok;
  if (!lines.next(line) || (tokens(line, tok), tok.empty() || tok[0] != "ply"))
    fail("not a PLY file: the first line must be 'ply'");
  if (!lines.next(line) || (tokens(line, tok), tok.size() < 3 || tok[0] != "format"))
    fail("PLY line 2 must be 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
  if (tok[1] == "ascii") encoding = PlyEncoding::Ascii;
  else if (tok[1] == "binary_little_endian") encoding = PlyEncoding::LittleEndian;
  else if (tok[1] == "binary_big_endian") encoding = PlyEncoding::BigEndian;
  else fail(fmt::format("PLY line 2: unknown format '{}'", tok[1]));

  while (lines.next(line)) {
    tokens(line, tok);
    const std::size_t n = lines.number();
    if (tok.empty()) fail(fmt::format("PLY header line {} is empty", n));
    if (tok[0] == "end_header") return lines.offset();
    if (tok[0] == "element") {
      long long count = 0;
      if (tok.size() < 3 || !parseInt(tok[2], 0, std::numeric_limits<long long>::max(), count))
        fail(fmt::format("PLY header line {}: expected 'element <name> <count>'", n));
      elements.push_back(
          PlyElement{std::string(tok[1]), static_cast<unsigned long long>(count), n, {}});
    } else if (tok[0] == "property") {
      if (elements.empty()) fail(fmt::format("PLY header line {}: property before any element", n));
      PlyProperty p;
      if (tok.size() >= 2 && tok[1] == "list") {
        if (tok.size() < 5)
          fail(fmt::format(
              "PLY header line {}: expected 'property list <count type> <item type> <name>'", n));
        auto count = plyType(tok[2]);
        auto item = plyType(tok[3]);
        if (!count || isReal(*count))
          fail(fmt::format("PLY header line {}: list count type '{}' is not an integer type", n,
                           tok[2]));
        if (!item) fail(fmt::format("PLY header line {}: unknown type '{}'", n, tok[3]));
        p = PlyProperty{std::string(tok[4]), n, true, *count, *item};
      } else {
        if (tok.size() < 3)
          fail(fmt::format("PLY header line {}: expected 'property <type> <name>'", n));
        auto type = plyType(tok[1]);
        if (!type) fail(fmt::format("PLY header line {}: unknown type '{}'", n, tok[1]));
        p = PlyProperty{std::string(tok[2]), n, false, PlyType::UInt8, *type};
      }
      elements.back().properties.push_back(p);
    }
    // comment, obj_info and other keywords are ignored, as CGAL does.
  }
  fail("the PLY header has no end_header line");
}

// A lower bound on the bytes one item of `e` occupies, to refuse absurd counts up front.
std::size_t minItemBytes(const PlyElement& e, PlyEncoding encoding) {
  std::size_t bytes = 0;
  for (const PlyProperty& p : e.properties)
    bytes += encoding == PlyEncoding::Ascii ? 2 : byteSize(p.list ? p.countType : p.type);
  return bytes;
}

// Reads binary scalars in the file's byte order.
class BinaryCursor {
 public:
  BinaryCursor(std::string_view data, bool bigEndian) : data_(data), bigEndian_(bigEndian) {}
  bool read(PlyType t, double& value) {
    const std::size_t n = byteSize(t);
    if (data_.size() - pos_ < n) return false;
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    if (bigEndian_)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case PlyType::Int8: {
        int8_t v;
        std::memcpy(&v, b, 1);
        value = v;
        break;
      }
      case PlyType::UInt8: {
        uint8_t v;
        std::memcpy(&v, b, 1);
        value = v;
        break;
      }
      case PlyType::Int16: {
        int16_t v;
        std::memcpy(&v, b, 2);
        value = v;
        break;
      }
      case PlyType::UInt16: {
        uint16_t v;
        std::memcpy(&v, b, 2);
        value = v;
        break;
      }
      case PlyType::Int32: {
        int32_t v;
        std::memcpy(&v, b, 4);
        value = v;
        break;
      }
      case PlyType::UInt32: {
        uint32_t v;
        std::memcpy(&v, b, 4);
        value = v;
        break;
      }
      case PlyType::Float32: {
        float v;
        std::memcpy(&v, b, 4);
        value = v;
        break;
      }
      case PlyType::Float64: {
        double v;
        std::memcpy(&v, b, 8);
        value = v;
        break;
      }
    }
    return true;
  }
  bool skip(std::size_t bytes) {
    if (data_.size() - pos_ < bytes) return false;
    pos_ += bytes;
    return true;
  }

 private:
  std::string_view data_;
  bool bigEndian_;
  std::size_t pos_ = 0;
};

// Whitespace-separated ASCII values, in any line layout (CGAL reads them with >>).
class AsciiCursor {
 public:
  explicit AsciiCursor(std::string_view data) : data_(data) {}
  bool next(std::string_view& tok) {
    while (pos_ < data_.size() && isSpace(data_[pos_])) ++pos_;
    std::size_t start = pos_;
    while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
    tok = data_.substr(start, pos_ - start);
    return !tok.empty();
  }
  bool read(PlyType t, double& value) {
    std::string_view tok;
    if (!next(tok)) return false;
    if (isReal(t)) return parseReal(tok, value);
    long long lo, hi, v;
    intRange(t, lo, hi);
    if (!parseInt(tok, lo, hi, v)) return false;
    value = static_cast<double>(v);
    return true;
  }

 private:
  std::string_view data_;
  std::size_t pos_ = 0;
};

// Where each property of a vertex element goes among the attributes kept: 0-2 the normal's
// x y z, 3-4 the texture coordinates, -1 nowhere. A normal needs all of nx ny nz, a uv
// both names of one pair, each a scalar (the first property of a name, as CGAL looks up).
struct AttributeSlots {
  std::vector<int> slot;  // per property
  bool normals = false, uvs = false;
};

AttributeSlots attributeSlots(const PlyElement& e) {
  AttributeSlots a;
  a.slot.assign(e.properties.size(), -1);
  auto indexOf = [&](std::string_view name) -> int {
    const PlyProperty* p = e.find(name);
    return p && !p->list ? static_cast<int>(p - e.properties.data()) : -1;
  };
  const int n[3] = {indexOf("nx"), indexOf("ny"), indexOf("nz")};
  if (n[0] >= 0 && n[1] >= 0 && n[2] >= 0) {
    a.normals = true;
    for (int k = 0; k < 3; ++k) a.slot[static_cast<std::size_t>(n[k])] = k;
  }
  const char* pairs[][2] = {
      {"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
  for (const auto& pair : pairs) {
    const int u = indexOf(pair[0]), v = indexOf(pair[1]);
    if (u < 0 || v < 0) continue;
    a.uvs = true;
    a.slot[static_cast<std::size_t>(u)] = 3;
    a.slot[static_cast<std::size_t>(v)] = 4;
    break;
  }
  return a;
}

template <class Cursor>
void walkBody(Cursor& cursor, const std::vector<PlyElement>& elements,
              unsigned long long vertexTotal, VertexAttributes* attributes) {
  for (const PlyElement& e : elements) {
    const bool vertex = e.isVertex();
    const PlyProperty* faceList = e.isFace() ? faceIndexList(e) : nullptr;
    AttributeSlots slots;
    if (vertex && attributes) slots = attributeSlots(e);
    if (slots.normals) attributes->normals.reserve(attributes->normals.size() + e.count);
    if (slots.uvs) attributes->uvs.reserve(attributes->uvs.size() + e.count);
    double kept[5] = {0, 0, 0, 0, 0};
    for (unsigned long long item = 0; item < e.count; ++item) {
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty& p = e.properties[i];
        auto truncated = [&] {
          fail(
              fmt::format("PLY data ends or is malformed in {} {} (counting from 0), property '{}'",
                          e.name, item, p.name));
        };
        double value = 0;
        if (!p.list) {
          if (!cursor.read(p.type, value)) truncated();
          if (vertex && !std::isfinite(value) && (p.name == "x" || p.name == "y" || p.name == "z"))
            fail(fmt::format("PLY vertex {} has a non-finite coordinate", item));
          // As the declared type holds it (ASCII text is read in double).
          if (!slots.slot.empty() && slots.slot[i] >= 0)
            kept[slots.slot[i]] = p.type == PlyType::Float32 ? static_cast<float>(value) : value;
          continue;
        }
        if (!cursor.read(p.countType, value)) truncated();
        if (value < 0 || value > static_cast<double>(kMaxFaceVertices))
          fail(fmt::format("PLY {} {}: list '{}' claims {} entries (the limit is {})", e.name, item,
                           p.name, value, kMaxFaceVertices));
        const auto entries = static_cast<std::size_t>(value);
        for (std::size_t k = 0; k < entries; ++k) {
          if (!cursor.read(p.type, value)) truncated();
          if (&p == faceList && (value < 0 || value >= static_cast<double>(vertexTotal)))
            fail(fmt::format("PLY face {} refers to vertex {}, but there are {} vertices", item,
                             value, vertexTotal));
        }
      }
      if (slots.normals) attributes->normals.emplace_back(kept[0], kept[1], kept[2]);
      if (slots.uvs) attributes->uvs.emplace_back(kept[3], kept[4]);
    }
  }
}

}  // namespace

MeshCounts checkPlyBytes(std::string_view bytes, VertexAttributes* attributes) {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  const std::size_t dataStart = parseHeader(bytes, encoding, elements);
  checkElementSemantics(elements);
  const std::string_view data = bytes.substr(dataStart);

  unsigned long long needed = 0, vertexTotal = 0, faceTotal = 0;
  for (const PlyElement& e : elements) {
    if (e.isVertex()) vertexTotal += e.count;
    if (e.isFace()) faceTotal += e.count;
    const std::size_t item = minItemBytes(e, encoding);
    if (item > 0 && e.count > (data.size() + 1) / item)
      fail(
          fmt::format("the PLY header declares {} '{}' elements, which need at least {} bytes, "
                      "but the data has {} bytes",
                      e.count, e.name, e.count * item, data.size()));
    needed += e.count * item;
  }
  if (needed > data.size() + 1)
    fail(
        fmt::format("the PLY data is too short for the elements the header declares ({} bytes "
                    "needed at least, {} present)",
                    needed, data.size()));

  if (encoding == PlyEncoding::Ascii) {
    AsciiCursor cursor(data);
    walkBody(cursor, elements, vertexTotal, attributes);
  } else {
    BinaryCursor cursor(data, encoding == PlyEncoding::BigEndian);
    walkBody(cursor, elements, vertexTotal, attributes);
  }
  // The walk has seen every element, so these counts are backed by data.
  return {static_cast<std::size_t>(vertexTotal), static_cast<std::size_t>(faceTotal)};
}

}  // namespace lucent
