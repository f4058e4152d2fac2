// Walks an ASCII OFF file the way CGAL 5.5 reads it (CGAL/IO/OFF.h, File_header_OFF_impl.h,
// File_scanner_OFF.h), so that CGAL never sees a file it would mishandle:
// - the header's vertex and face counts size vectors before anything is read, and a face's
//   own vertex count sizes that polygon: all are checked against the data that is there;
// - colour values (COFF) are fetched from a line's numbers without a bounds check once any
//   vertex or face had colours: every later line must then carry 1 or at least 3 of them;
// - texture (ST), homogeneous (4), n-dimensional (n) variants and binary OFF are read
//   inconsistently by that reader (binary faces skip the colour count the format defines),
//   so they are refused with a message saying so.
// Comments: '#' up to the end of the line, and lines that start with '#'.
// The normals of NOFF and CNOFF vertices are kept for the caller (CGAL's reader drops them).
#include "mesh_file_check.h"

#include "mesh_error.h"
#include "mesh_text.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <limits>

namespace lucent {
namespace {

using namespace meshtext;

[[noreturn]] void fail(const std::string& message) { throw MeshError(message); }

class OffCursor {
 public:
  explicit OffCursor(std::string_view text) : text_(text) {}

  // CGAL's skip_comment_OFF: whitespace, then whole lines starting with '#'.
  void skipComments() {
    skipSpace();
    while (pos_ < text_.size() && text_[pos_] == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      skipSpace();
    }
  }
  void skipSpace() {
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
  }
  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }

  std::string_view word() {  // a run of letters and digits
    std::size_t start = pos_;
    while (pos_ < text_.size() && std::isalnum(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  // istream >> int: optional sign and digits, stopping at the first other character.
  bool integer(long long& value, std::string_view& text) {
    skipSpace();
    std::size_t start = pos_;
    if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    text = text_.substr(start, pos_ - start);
    return parseInt(text, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), value);
  }

  // The rest of the line, without its '#' comment; the cursor moves past the '\n'.
  std::string_view restOfLine() {
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    return line;
  }

  std::size_t lineNumber() {  // of the current position, counting from 1; the cursor only moves on
    for (; counted_ < pos_ && counted_ < text_.size(); ++counted_) line_ += text_[counted_] == '\n';
    return line_;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t counted_ = 0, line_ = 1;
};

struct OffHeader {
  bool colours = false;
  bool normals = false;
  long long vertices = 0, faces = 0;
};

OffHeader parseHeader(OffCursor& in) {
  in.skipComments();
  if (in.atEnd()) fail("the OFF file holds only comments");
  const std::string_view keyword = in.word();
  OffHeader h;
  auto endsWith = [&](std::string_view tail) {
    return keyword.size() >= tail.size() && keyword.substr(keyword.size() - tail.size()) == tail;
  };
  if (endsWith("SKEL")) fail("SKEL files hold skeletons, not surfaces");
  if (!endsWith("OFF"))
    fail(fmt::format("not an OFF file: it starts with '{}' instead of the keyword OFF",
                     std::string(keyword.substr(0, 20))));
  const std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix == "C" || prefix == "CN") h.colours = true;
  if (prefix == "N" || prefix == "CN") h.normals = true;
  if (!prefix.empty() && prefix != "C" && prefix != "N" && prefix != "CN")
    fail(
        fmt::format("OFF variant '{}' is not supported (texture, homogeneous and n-dimensional "
                    "OFF are not read reliably); use OFF, COFF, NOFF or CNOFF",
                    std::string(keyword.substr(0, 20))));
  in.skipComments();
  if (!in.atEnd() && std::isalpha(static_cast<unsigned char>(in.peek()))) {
    if (in.word() == "BINARY")
      fail("binary OFF is not supported (CGAL 5.5 misreads its faces); use ASCII OFF, PLY or STL");
    fail("the OFF keyword must be followed by the vertex, face and edge counts");
  }
  long long edges = 0;
  for (long long* count : {&h.vertices, &h.faces, &edges}) {
    std::string_view text;
    if (!in.integer(*count, text)) {
      if (text.empty())
        fail("the OFF header must give three counts (vertices, faces, edges) after the keyword");
      fail(fmt::format("the OFF header count '{}' is not a number the reader can hold",
                       std::string(text.substr(0, 24))));
    }
  }
  if (h.vertices < 0 || h.faces < 0) fail("the OFF header has a negative count");
  if (static_cast<unsigned long long>(h.vertices) > kMaxMeshVertices)
    fail(fmt::format("the OFF header declares {} vertices; the limit is {}", h.vertices,
                     kMaxMeshVertices));
  if (static_cast<unsigned long long>(h.faces) > kMaxMeshFaces)
    fail(fmt::format("the OFF header declares {} faces; the limit is {}", h.faces, kMaxMeshFaces));
  return h;
}

// The numbers of the next data line, as CGAL fetches it; false at the end of the data.
bool nextLine(OffCursor& in, std::vector<std::string_view>& tok, std::vector<double>& numbers,
              std::size_t& line) {
  in.skipComments();
  if (in.atEnd()) return false;
  line = in.lineNumber();
  tokens(in.restOfLine(), tok);
  numbers.resize(tok.size());
  for (std::size_t i = 0; i < tok.size(); ++i)
    if (!parseReal(tok[i], numbers[i]))
      fail(fmt::format("OFF line {}: '{}' is not a number", line,
                       std::string(tok[i].substr(0, 20))));
  return true;
}

// Once CGAL has seen colours it reads them from every later line: one colour-map index, or at
// least three components, must be there.
void checkColours(std::size_t count, const double* values, bool& seen, std::size_t line) {
  if (count != 0) seen = true;
  if (!seen) return;
  if (count == 2 || count == 0)
    fail(fmt::format("OFF line {}: {} colour values (expected 1, 3 or 4, as on the earlier lines)",
                     line, count));
  if (count == 1 && !(values[0] >= 0 && values[0] <= 1e6))
    fail(fmt::format("OFF line {}: colour index {} is not valid", line, values[0]));
  // CGAL converts r g b to unsigned char as they are when all three are whole numbers, else
  // times 255; a value outside 0..255 after that is undefined behaviour in the conversion
  // (found by mesh_off_fuzz: tests/fuzz/crashes/mesh_off/).
  if (count >= 3) {
    const bool whole = std::floor(values[0]) == values[0] && std::floor(values[1]) == values[1] &&
                       std::floor(values[2]) == values[2];
    for (int i = 0; i < 3; ++i) {
      const double byte = whole ? values[i] : values[i] * 255;
      if (!(byte >= 0 && byte < 256))
        fail(fmt::format(
            "OFF line {}: colour value {} is outside 0 to 255 (whole numbers) or 0 to 1", line,
            values[i]));
    }
  }
}

}  // namespace

void checkOffBytes(std::string_view bytes, VertexAttributes* attributes) {
  OffCursor in(bytes);
  const OffHeader h = parseHeader(in);
  std::vector<std::string_view> tok;
  std::vector<double> numbers;
  std::size_t line = 0;
  bool vertexColours = false, faceColours = false;
  const std::size_t coords = h.normals ? 6 : 3;
  if (attributes && h.normals) attributes->normals.reserve(static_cast<std::size_t>(h.vertices));

  for (long long v = 0; v < h.vertices; ++v) {
    if (!nextLine(in, tok, numbers, line))
      fail(fmt::format("the OFF file ends after {} of its {} vertices", v, h.vertices));
    if (numbers.size() < coords)
      fail(fmt::format("OFF line {}: a vertex needs {} numbers, found {}", line, coords,
                       numbers.size()));
    if (h.colours)
      checkColours(numbers.size() - coords, numbers.data() + coords, vertexColours, line);
    // CGAL reads a NOFF vertex as x y z nx ny nz, before any colour.
    if (attributes && h.normals)
      attributes->normals.emplace_back(numbers[3], numbers[4], numbers[5]);
  }
  for (long long f = 0; f < h.faces; ++f) {
    if (!nextLine(in, tok, numbers, line))
      fail(fmt::format("the OFF file ends after {} of its {} faces", f, h.faces));
    long long n = 0;
    if (!parseInt(tok[0], 0, static_cast<long long>(kMaxFaceVertices), n))
      fail(fmt::format("OFF line {}: '{}' is not a face vertex count between 0 and {}", line,
                       std::string(tok[0].substr(0, 20)), kMaxFaceVertices));
    if (tok.size() < static_cast<std::size_t>(n) + 1)
      fail(fmt::format("OFF line {}: the face announces {} vertices but lists {}", line, n,
                       tok.size() - 1));
    for (long long k = 1; k <= n; ++k) {
      long long index = 0;
      if (!parseInt(tok[k], 0, h.vertices - 1, index))
        fail(fmt::format("OFF line {}: vertex index '{}' is not between 0 and {}", line,
                         std::string(tok[k].substr(0, 20)), h.vertices - 1));
    }
    if (h.colours) checkColours(tok.size() - (n + 1), numbers.data() + n + 1, faceColours, line);
  }
}

}  // namespace lucent
