#include "source_file.h"

#include <algorithm>
#include <fstream>
#include <functional>

namespace lucent {

std::optional<std::string> readSceneText(const std::filesystem::path& path, std::string& text) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return "no such file";
  if (status.type() == fs::file_type::directory) return "it is a folder, not a file";
  if (ec) return "it cannot be examined: " + ec.message();
  if (status.type() != fs::file_type::regular) return "it is not a regular file";
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return "its size cannot be read: " + ec.message();
  if (size > kMaxSceneFileBytes)
    return "it is too large (" + std::to_string(size) + " bytes; the limit is " +
           std::to_string(kMaxSceneFileBytes) + " bytes)";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "the file cannot be read";
  text.assign(static_cast<size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) return "the file cannot be read completely";
  return std::nullopt;
}

SourceFile::SourceFile(std::string display, std::filesystem::path folder, std::string text)
    : display_(std::move(display)), folder_(std::move(folder)), text_(std::move(text)) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n') lineStarts_.push_back(i + 1);
}

std::optional<Diagnostic> SourceFile::parse() {
  // In-place parsing keeps names and values inside text_, so a pointer minus text_.data()
  // is a byte offset for attributes too (pugixml's offset_debug() covers nodes only).
  // No document buffer is copied, which also halves the memory of large inline meshes.
  pugi::xml_parse_result r =
      doc_.load_buffer_inplace(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
  if (r) return std::nullopt;
  Diagnostic d;
  d.loc = locAt(r.offset < 0 ? 0 : static_cast<size_t>(r.offset));
  d.message = std::string("XML syntax error: ") + r.description();
  return d;
}

SourceLoc SourceFile::locAt(size_t offset) const {
  auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  size_t line = static_cast<size_t>(it - lineStarts_.begin());  // 1-based
  size_t col = offset - lineStarts_[line - 1] + 1;
  return {display_, static_cast<int>(line), static_cast<int>(col)};
}

std::optional<size_t> SourceFile::offsetOf(const char* p) const {
  std::less_equal<const char*> le;
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  if (p && le(begin, p) && le(p, end)) return static_cast<size_t>(p - begin);
  return std::nullopt;
}

std::optional<SourceLoc> SourceFile::locOf(const char* p) const {
  if (auto off = offsetOf(p)) return locAt(*off);
  return std::nullopt;
}

SourceLoc SourceFile::loc(pugi::xml_node element) const {
  if (auto off = offsetOf(element.name()); off && *off > 0) return locAt(*off - 1);
  return fileLoc();
}

SourceLoc SourceFile::nameLoc(pugi::xml_attribute attr, pugi::xml_node owner) const {
  if (auto off = offsetOf(attr.name())) return locAt(*off);
  return loc(owner);
}

SourceLoc SourceFile::valueLoc(pugi::xml_attribute attr, pugi::xml_node owner) const {
  // An empty value may point at pugixml's shared empty string: fall back to the name.
  if (*attr.value() != '\0')
    if (auto off = offsetOf(attr.value())) return locAt(*off);
  return nameLoc(attr, owner);
}

}  // namespace lucent
