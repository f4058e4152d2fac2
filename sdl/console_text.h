// #debug text as POV-Ray 3.7 prints it. It goes through two line buffers: the parser cuts
// the text into lines of at most 160 characters, then the front end prints each of those
// cut at 80 columns; a line too long is cut at a space among its last quarter (40, then 20
// characters), or at the width when there is none there. A last line with no line end is
// never printed (POV-Ray 3.7 does not flush the parser's buffer).
#pragma once

#include <string>

namespace lucent::sdl {

class DebugPrinter {
 public:
  // The lines that `text` completes, as printed.
  std::string add(const std::string& text);

 private:
  std::string buffer_;
};

// A whole #debug output as POV-Ray prints it.
std::string povPrinted(const std::string& text);

}  // namespace lucent::sdl
