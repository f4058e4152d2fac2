#include "console_text.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace lucent::sdl {

namespace {

constexpr size_t kParserWidth = 160;  // the parser's message buffer
constexpr size_t kConsoleWidth = 80;  // the front end's streams

// Takes the complete lines out of `buffer`: up to a line end, or cut at `width`
// characters (at a space among the last quarter if there is one, which then begins the
// next line). What is left is the unfinished line.
std::vector<std::string> takeLines(std::string& buffer, size_t width) {
  std::vector<std::string> lines;
  size_t start = 0, i = 0;
  while (i < buffer.size()) {
    if (buffer[i] == '\n' || buffer[i] == '\r') {
      lines.push_back(buffer.substr(start, i - start));
      start = i + 1;
    } else if (i - start >= width) {
      const size_t limit = std::min(width / 4, i);
      size_t back = 0;
      while (back < limit && !std::isspace(static_cast<unsigned char>(buffer[i - back]))) ++back;
      if (back == limit) back = 0;
      i -= back;
      lines.push_back(buffer.substr(start, i - start));
      start = i;
      continue;
    }
    ++i;
  }
  buffer.erase(0, start);
  return lines;
}

// One line of the parser's as the front end prints it.
std::string printed(const std::string& line) {
  std::string buffer = line + "\n", out;
  for (const std::string& l : takeLines(buffer, kConsoleWidth)) out += l + "\n";
  return out;
}

}  // namespace

std::string DebugPrinter::add(const std::string& text) {
  buffer_ += text;
  std::string out;
  for (const std::string& line : takeLines(buffer_, kParserWidth)) out += printed(line);
  return out;
}

std::string povPrinted(const std::string& text) { return DebugPrinter().add(text); }

}  // namespace lucent::sdl
