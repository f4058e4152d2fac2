// One scene file held in memory: its text parsed in place by pugixml, so that every
// element and attribute keeps a pointer into the text and errors can say file:line:col.
#pragma once

#include "diagnostics.h"

#include <pugixml.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lucent {

// A scene file (or an include) larger than this is refused before it is read: large inline
// meshes fit, while `lucent render /dev/zero` or a runaway generated file cannot eat the
// machine's memory.
constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{1} << 30;  // 1 GiB

// Reads a whole scene file into `text`. It must be a regular file (not a folder, device or
// pipe, which could be endless) of at most kMaxSceneFileBytes. Returns the problem in words,
// or nothing on success.
std::optional<std::string> readSceneText(const std::filesystem::path& path, std::string& text);

class SourceFile {
 public:
  // `display` names the file in messages; `folder` anchors the relative paths it contains.
  SourceFile(std::string display, std::filesystem::path folder, std::string text);
  SourceFile(const SourceFile&) = delete;  // pugixml's nodes point into text_
  SourceFile& operator=(const SourceFile&) = delete;

  // Parses the text; on an XML syntax error returns it, located where pugixml stopped.
  std::optional<Diagnostic> parse();

  const std::string& display() const { return display_; }
  const std::filesystem::path& folder() const { return folder_; }
  pugi::xml_node root() const { return doc_.document_element(); }

  SourceLoc fileLoc() const { return {display_, 0, 0}; }
  SourceLoc locAt(size_t offset) const;
  // The element's '<'.
  SourceLoc loc(pugi::xml_node element) const;
  // The attribute's name, and the first character of its value (inside the quotes).
  SourceLoc nameLoc(pugi::xml_attribute attr, pugi::xml_node owner) const;
  SourceLoc valueLoc(pugi::xml_attribute attr, pugi::xml_node owner) const;
  // The character at `offset` of the attribute's value as parsed: pugixml decoded entities
  // (&lt; is one '<') and line ends in place, so the offset is mapped back through them.
  SourceLoc locInValue(pugi::xml_attribute attr, pugi::xml_node owner, size_t offset) const;
  // Where a pointer into the parsed text points (text content, say).
  std::optional<SourceLoc> locOf(const char* p) const;

 private:
  // Byte offset of a pointer into the parsed buffer, if it points there.
  std::optional<size_t> offsetOf(const char* p) const;

  std::string display_;
  std::filesystem::path folder_;
  std::string text_;                // pugixml parses it in place: never reallocated after parse()
  std::vector<size_t> lineStarts_;  // computed before parsing rewrites newlines in values
  // Where the text shrinks when parsed (an entity, a "\r\n"): offset and bytes lost.
  std::vector<std::pair<size_t, size_t>> shrinks_;
  pugi::xml_document doc_;
};

}  // namespace lucent
