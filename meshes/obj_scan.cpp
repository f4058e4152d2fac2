#include "obj_scan.h"

#include "mesh_error.h"
#include "mesh_file_check.h"
#include "mesh_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lucent {
namespace {

using namespace meshtext;

// Statements CGAL's reader accepts and skips (CGAL/IO/OBJ.h, 5.5). Anything else makes it
// refuse the file, so we refuse it first, with the line number.
constexpr std::array<std::string_view, 43> kSkipped = {
    "vp",       "bevel",    "lod",        "ctech",     "c_interp", "usemap",   "usemtl", "stech",
    "d_interp", "mtllib",   "shadow_obj", "trace_obj", "o",        "g",        "s",      "p",
    "cstype",   "deg",      "step",       "bmat",      "con",      "curv",     "curv2",  "surf",
    "parm",     "trim",     "hole",       "scrv",      "sp",       "end",      "surf_1", "q0_1",
    "q1_1",     "curv2d_1", "surf_2",     "q0_2",      "q1_2",     "curv2d_2", "bsp",    "bzp",
    "cdc",      "cdp",      "res"};

[[noreturn]] void fail(std::size_t line, const std::string& message) {
  throw MeshError(fmt::format("OBJ line {}: {}", line, message));
}

std::string shown(std::string_view tok) { return std::string(tok.substr(0, 24)); }

// The largest positive reference of one kind, remembered to check it once the file is read
// (CGAL, like most readers, accepts references to vertices defined later).
struct MaxRef {
  long long value = 0;
  std::size_t line = 0;
  void note(long long v, std::size_t l) {
    if (v > value) value = v, line = l;
  }
};

// Resolves an OBJ reference (1-based, or negative = relative to the count so far) to 0-based.
long long resolve(long long ref, std::size_t countSoFar, const char* what, std::size_t line,
                  MaxRef& max) {
  if (ref == 0) fail(line, fmt::format("{} index 0 is invalid (OBJ counts from 1)", what));
  if (ref > 0) {
    max.note(ref, line);
    return ref - 1;
  }
  if (static_cast<unsigned long long>(-ref) > countSoFar)
    fail(line, fmt::format("relative {} index {} reaches before the first {}", what, ref, what));
  return static_cast<long long>(countSoFar) + ref;
}

}  // namespace

ObjScan scanObj(std::string& bytes) {
  if (bytes.size() >= 2 &&
      ((bytes[0] == '\xFE' && bytes[1] == '\xFF') || (bytes[0] == '\xFF' && bytes[1] == '\xFE')))
    throw MeshError("the OBJ file is UTF-16 text; save it as ASCII or UTF-8");
  if (bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) bytes.replace(0, 3, "   ");  // UTF-8 BOM
  // CGAL skips from one face corner to the next with ignore(256, ' '): tabs would hide corners.
  std::replace(bytes.begin(), bytes.end(), '\t', ' ');

  ObjScan scan;
  MaxRef maxVertex, maxTexcoord, maxNormal;
  Lines lines(bytes);
  std::string_view line;
  std::vector<std::string_view> tok;
  const long long intMin = std::numeric_limits<int>::min(),
                  intMax = std::numeric_limits<int>::max();

  while (lines.next(line)) {
    const std::size_t n = lines.number();
    tokens(line, tok);
    if (tok.empty()) continue;
    const std::string_view s = tok[0];
    auto numbers = [&](std::size_t needed, double* out) {
      if (tok.size() < needed + 1) fail(n, fmt::format("'{}' needs {} numbers", shown(s), needed));
      for (std::size_t i = 0; i < needed; ++i)
        if (!parseReal(tok[i + 1], out[i]))
          fail(n, fmt::format("'{}' is not a finite number", shown(tok[i + 1])));
    };

    if (s == "v") {
      double p[3];
      numbers(3, p);
      if (++scan.vertexCount > kMaxMeshVertices)
        fail(n, fmt::format("more than {} vertices", kMaxMeshVertices));
    } else if (s == "vt") {
      double uv[2] = {0, 0};
      numbers(1, uv);  // v defaults to 0 (OBJ specification, appendix B1)
      if (tok.size() > 2 && tok[2].front() != '#' && !parseReal(tok[2], uv[1]))
        fail(n, fmt::format("'{}' is not a finite number", shown(tok[2])));
      scan.texcoords.emplace_back(uv[0], uv[1]);
    } else if (s == "vn") {
      double v[3];
      numbers(3, v);
      // A zero normal (exporters write them for degenerate faces) cannot be used; the corners
      // that name it count as corners without a normal.
      const Vec3 normal(v[0], v[1], v[2]);
      const double length = glm::length(normal);
      scan.normals.push_back(length > 0 && std::isfinite(length) ? normal / length : Vec3(0));
    } else if (s == "f") {
      if (scan.faceCount() >= kMaxMeshFaces)
        fail(n, fmt::format("more than {} faces", kMaxMeshFaces));
      std::size_t cornerCount = 0;
      for (std::size_t i = 1; i < tok.size(); ++i) {
        const std::string_view c = tok[i];
        if (c.front() == '#') break;  // a comment ends the statement, as for CGAL's >>
        if (++cornerCount > kMaxFaceVertices)
          fail(n, fmt::format("a face with more than {} corners", kMaxFaceVertices));
        // v, v/vt, v//vn or v/vt/vn
        std::string_view parts[3];
        std::size_t count = 0, start = 0;
        for (std::size_t k = 0; k <= c.size(); ++k) {
          if (k == c.size() || c[k] == '/') {
            if (count == 3)
              fail(n,
                   fmt::format("'{}' is not a face corner (v, v/vt, v//vn or v/vt/vn)", shown(c)));
            parts[count++] = c.substr(start, k - start);
            start = k + 1;
          }
        }
        long long v = 0, t = 0, nn = 0;
        auto parsePart = [&](std::string_view p, long long& out) {
          if (!parseInt(p, intMin, intMax, out))
            fail(n, fmt::format("'{}' is not a face corner (v, v/vt, v//vn or v/vt/vn)", shown(c)));
        };
        parsePart(parts[0], v);
        resolve(v, scan.vertexCount, "vertex", n, maxVertex);
        ObjScan::Corner corner;
        if (count >= 2 && !parts[1].empty()) {
          parsePart(parts[1], t);
          corner.texcoord = static_cast<int32_t>(
              resolve(t, scan.texcoords.size(), "texture coordinate", n, maxTexcoord));
        }
        if (count == 3) {
          parsePart(parts[2], nn);
          corner.normal =
              static_cast<int32_t>(resolve(nn, scan.normals.size(), "normal", n, maxNormal));
        }
        scan.everyCornerHasTexcoord &= corner.texcoord >= 0;
        scan.everyCornerHasNormal &= corner.normal >= 0;
        scan.corners.push_back(corner);
      }
      scan.faceStart.push_back(static_cast<uint32_t>(scan.corners.size()));
    } else if (s == "l") {
      // A polyline has no surface: renderers skip it. CGAL would refuse the file, so the
      // statement becomes a comment in the buffer it reads.
      bytes[static_cast<std::size_t>(s.data() - bytes.data())] = '#';
    } else if (s.front() == '#' ||
               std::find(kSkipped.begin(), kSkipped.end(), s) != kSkipped.end()) {
      // comment, or a statement without geometry
    } else {
      fail(n, fmt::format("unknown OBJ statement '{}'", shown(s)));
    }
  }

  if (static_cast<unsigned long long>(maxVertex.value) > scan.vertexCount)
    fail(maxVertex.line, fmt::format("a face uses vertex {}, but the file has {} vertices",
                                     maxVertex.value, scan.vertexCount));
  if (static_cast<unsigned long long>(maxTexcoord.value) > scan.texcoords.size())
    fail(maxTexcoord.line, fmt::format("a face uses texture coordinate {}, but the file has {}",
                                       maxTexcoord.value, scan.texcoords.size()));
  if (static_cast<unsigned long long>(maxNormal.value) > scan.normals.size())
    fail(maxNormal.line, fmt::format("a face uses normal {}, but the file has {}", maxNormal.value,
                                     scan.normals.size()));
  for (const ObjScan::Corner& c : scan.corners)
    if (c.normal >= 0 && scan.normals[static_cast<std::size_t>(c.normal)] == Vec3(0))
      scan.everyCornerHasNormal = false;
  if (scan.vertexCount == 0) throw MeshError("the OBJ file has no vertices ('v' statements)");
  if (scan.faceCount() == 0)
    throw MeshError("the OBJ file has no faces ('f' statements); points and lines have no surface");
  return scan;
}

}  // namespace lucent
