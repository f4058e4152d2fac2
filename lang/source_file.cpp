#include "source_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <functional>

namespace lucent {

namespace {

// Why `path` cannot be read, examined as std::filesystem examines it.
std::string whyUnreadable(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return "no such file";
  if (status.type() == fs::file_type::directory) return "it is a folder, not a file";
  if (ec) return "it cannot be examined: " + ec.message();
  if (status.type() != fs::file_type::regular) return "it is not a regular file";
  return "the file cannot be read";
}

}  // namespace

// One open, fstat and read (a scene reads many includes; streams and separate stat calls
// cost more than the reading). O_NONBLOCK: a FIFO is refused, never waited on.
std::optional<std::string> readSceneText(const std::filesystem::path& path, std::string& text) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return whyUnreadable(path);
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) return whyUnreadable(path);
  if (S_ISDIR(st.st_mode)) return "it is a folder, not a file";
  if (!S_ISREG(st.st_mode)) return "it is not a regular file";
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > kMaxSceneFileBytes)
    return "it is too large (" + std::to_string(size) + " bytes; the limit is " +
           std::to_string(kMaxSceneFileBytes) + " bytes)";
  text.assign(static_cast<size_t>(size), '\0');
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::read(fd, text.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return "the file cannot be read";
    if (n == 0) return "the file cannot be read completely";
    done += static_cast<size_t>(n);
  }
  return std::nullopt;
}

SourceFile::SourceFile(std::string display, std::filesystem::path folder, std::string text)
    : display_(std::move(display)), folder_(std::move(folder)), text_(std::move(text)) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i) {
    char c = text_[i];
    if (c == '\n') lineStarts_.push_back(i + 1);
    else if (c == '\r' && i + 1 < text_.size() && text_[i + 1] == '\n') shrinks_.emplace_back(i, 1);
    else if (c == '&') {
      size_t end = text_.find(';', i);
      if (end == std::string::npos || end - i > 12) continue;
      size_t decoded = 1;
      if (i + 1 < end && text_[i + 1] == '#') {  // a character reference: its UTF-8 length
        bool hex = i + 2 < end && (text_[i + 2] == 'x' || text_[i + 2] == 'X');
        unsigned long cp = std::strtoul(text_.c_str() + i + (hex ? 3 : 2), nullptr, hex ? 16 : 10);
        decoded = cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4;
      }
      if (end + 1 - i > decoded) shrinks_.emplace_back(i, end + 1 - i - decoded);
    }
  }
}

std::optional<Diagnostic> SourceFile::parse() {
  // In-place parsing keeps names and values inside text_, so a pointer minus text_.data()
  // is a byte offset for attributes too (pugixml's offset_debug() covers nodes only).
  // No document buffer is copied, which also halves the memory of large inline meshes.
  pugi::xml_parse_result r = doc_.load_buffer_inplace(text_.data(), text_.size(),
                                                      pugi::parse_default, pugi::encoding_utf8);
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

SourceLoc SourceFile::locInValue(pugi::xml_attribute attr, pugi::xml_node owner,
                                 size_t offset) const {
  auto start = *attr.value() ? offsetOf(attr.value()) : std::nullopt;
  if (!start) return valueLoc(attr, owner);
  size_t lost = 0;
  auto it = std::lower_bound(shrinks_.begin(), shrinks_.end(), std::make_pair(*start, size_t{0}));
  for (; it != shrinks_.end(); ++it) {
    size_t decodedAt = it->first - *start - lost;  // where this entity's character is
    if (decodedAt >= offset) break;
    lost += it->second;
  }
  return locAt(*start + offset + lost);
}

}  // namespace lucent
