// libpng's error reporting for the built-in PNG writer and reader. libpng reports an error
// through a callback that must not return: it longjmps back to the setjmp of the function
// driving libpng. Those functions hold no C++ object with a destructor, so the jump skips
// nothing.
#pragma once

#include <png.h>

#include <cstdio>

namespace lucent::builtin {

// Where the callback leaves libpng's message (the png struct's error pointer).
struct ErrorSink {
  char message[256];
};

[[noreturn]] inline void onPngError(png_structp png, png_const_charp message) {
  auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message ? message : "libpng error");
  png_longjmp(png, 1);
}

inline void ignorePngWarning(png_structp, png_const_charp) {}

}  // namespace lucent::builtin
