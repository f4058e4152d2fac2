// Text of a POV-Ray scene: numbers, vectors, colours and matrices in POV-Ray syntax, an
// indenting line buffer, and the errors and warnings found while writing.
#pragma once

#include "scenegraph/source_loc.h"

#include "primitives/math.h"

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// Something the export could not express (an error: no file is written) or expressed only
// approximately (a warning). The message names the scene element.
struct PovIssue {
  bool error = false;
  SourceLoc loc;
  std::string message;

  // "file:line:col: error: message", as the parser prints its diagnostics.
  std::string str() const;
};

// The shortest text that reads back as the same double (fmt's round-trip format), with
// an explicit exponent sign POV-Ray accepts ("1e-07"); never inf or nan (the caller checks).
std::string povNumber(double v);
// <x, y, z>
std::string povVector(const Vec3& v);
// A value POV-Ray keeps as a float (colours, finish amounts), written as the shortest text
// of its float value: 0.8 rather than 0.800000011920929.
std::string povFloat(double v);
// rgb <r, g, b>: always the five-channel-safe `rgb` form (a bare `color 0.5` would set
// filter and transmit too: POV-Ray spreads one float over all five channels). Channels
// as povFloat.
std::string povRgb(const Color& c);
std::string povRgb(const Vec3& c);
// rgbft <r, g, b, f, t>
std::string povRgbft(const Vec3& c, double filter, double transmit);
// matrix <...>: POV-Ray's row-vector layout x'_k = Σ_i x_i·m_ik + t_k, so the twelve
// numbers are the columns of our column-vector matrix (the images of x, y, z, then the
// translation), written in order. Requires an affine matrix (last row 0 0 0 1).
std::string povMatrix(const Mat4& worldFromObject);
bool isIdentity(const Mat4& m);

// A POV-Ray identifier made of `prefix` and the letters, digits and underscores of `name`
// (others become '_'), at most 40 characters: "M3_brick_red".
std::string povIdentifier(std::string_view prefix, std::string_view name);

// A string literal for file names: POV-Ray strings take backslash escapes.
std::string povString(std::string_view text);

class PovWriter {
 public:
  // One line at the current indentation.
  void line(std::string_view text);
  // "text {" (and "  // comment") and one level deeper.
  void open(std::string_view text, std::string_view comment = {});
  // "}" one level up.
  void close();
  void blank() { text_ += '\n'; }
  // Appends another writer's text (its own indentation is kept as written).
  void append(const PovWriter& other) { text_ += other.text_; }

  const std::string& text() const { return text_; }

 private:
  std::string text_;
  int depth_ = 0;
};

// Errors and warnings, in the order found; a warning given for one construct is given
// once even when the construct is written many times (a material used by 100 shapes).
class PovIssues {
 public:
  void error(const SourceLoc& loc, std::string message);
  void warning(const SourceLoc& loc, std::string message);

  bool hasErrors() const;
  const std::vector<PovIssue>& all() const { return all_; }

 private:
  void add(bool error, const SourceLoc& loc, std::string message);
  std::vector<PovIssue> all_;
};

}  // namespace lucent
