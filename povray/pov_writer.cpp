#include "pov_writer.h"

#include <fmt/core.h>

#include <cctype>

namespace lucent {

std::string PovIssue::str() const {
  std::string where = loc.str();
  return fmt::format("{}{}{}: {}", where, where.empty() ? "" : ": ", error ? "error" : "warning",
                     message);
}

std::string povNumber(double v) {
  if (v == 0.0) return "0";  // also for -0: "-0" reads fine but looks like a mistake
  return fmt::format("{}", v);
}

std::string povVector(const Vec3& v) {
  return fmt::format("<{}, {}, {}>", povNumber(v.x), povNumber(v.y), povNumber(v.z));
}

std::string povFloat(double v) {
  // The shortest text of the float reads back as the same float in POV-Ray.
  float f = static_cast<float>(v);
  if (f == 0.0f) return "0";
  return fmt::format("{}", f);
}

std::string povRgb(const Vec3& c) {
  return fmt::format("rgb <{}, {}, {}>", povFloat(c.x), povFloat(c.y), povFloat(c.z));
}

std::string povRgb(const Color& c) { return povRgb(Vec3(c.r, c.g, c.b)); }

std::string povRgbft(const Vec3& c, double filter, double transmit) {
  return fmt::format("rgbft <{}, {}, {}, {}, {}>", povFloat(c.x), povFloat(c.y), povFloat(c.z),
                     povFloat(filter), povFloat(transmit));
}

std::string povMatrix(const Mat4& m) {
  // glm is column-major: m[c] is column c, the image of axis c (or the translation).
  std::string out = "matrix <";
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) {
      out += povNumber(m[c][r]);
      if (c != 3 || r != 2) out += (r == 2 ? ",  " : ", ");
    }
  }
  return out + ">";
}

bool isIdentity(const Mat4& m) { return m == Mat4(1.0); }

std::string povIdentifier(std::string_view prefix, std::string_view name) {
  std::string id(prefix);
  if (!name.empty()) id += '_';
  for (char ch : name) {
    unsigned char u = static_cast<unsigned char>(ch);
    id += (std::isalnum(u) && u < 128) ? ch : '_';
  }
  if (id.size() > 40) id.resize(40);
  return id;
}

std::string povString(std::string_view text) {
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

void PovWriter::line(std::string_view text) {
  text_.append(static_cast<size_t>(depth_) * 2, ' ');
  text_ += text;
  text_ += '\n';
}

void PovWriter::open(std::string_view text, std::string_view comment) {
  std::string head = std::string(text) + " {";
  if (!comment.empty()) head += "  // " + std::string(comment);
  line(head);
  ++depth_;
}

void PovWriter::close() {
  if (depth_ > 0) --depth_;
  line("}");
}

void PovIssues::add(bool error, const SourceLoc& loc, std::string message) {
  for (const PovIssue& i : all_)
    if (i.error == error && i.message == message && i.loc.str() == loc.str()) return;
  all_.push_back({error, loc, std::move(message)});
}

void PovIssues::error(const SourceLoc& loc, std::string message) {
  add(true, loc, std::move(message));
}

void PovIssues::warning(const SourceLoc& loc, std::string message) {
  add(false, loc, std::move(message));
}

bool PovIssues::hasErrors() const {
  for (const PovIssue& i : all_)
    if (i.error) return true;
  return false;
}

}  // namespace lucent
