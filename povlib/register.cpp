#include "register.h"

#include "lang/pov_library.h"

#include <string_view>

namespace lucent {

extern const std::string_view kPovLibraryXml;  // pov_library_text.cpp, made by the build

void registerPovLibrary() { setPovLibraryText(kPovLibraryXml); }

}  // namespace lucent
