#include "image_reading.h"

#include "address_sanitizer.h"
#include "builtin/builtin_images.h"

#if defined(LUCENT_ASAN)
#include <sanitizer/lsan_interface.h>
#endif

namespace lucent {

// OpenImageIO 2.4's PNG reader leaks one string on a damaged or truncated file (libpng
// longjmps past its destructor, as when writing: app/image_output.cpp, writeImageFile),
// and damaged files are what the bad-input corpus feeds the readers: LeakSanitizer
// ignores what opening and decoding allocate.
std::unique_ptr<ImageReader> openImageReader(const std::string& path, std::string& error) {
  if (auto reader = builtinOpenFile(path, error); reader || !error.empty()) return reader;
#if defined(LUCENT_ASAN)
  __lsan::ScopedDisabler ignoreLibraryLeak;
#endif
  return imagePlugin().openFile(path, error);
}

std::string readImagePixels(ImageReader& in, float* out) {
#if defined(LUCENT_ASAN)
  __lsan::ScopedDisabler ignoreLibraryLeak;
#endif
  return in.readPixels(out);
}

}  // namespace lucent
