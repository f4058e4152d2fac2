// The library of scene files that ships inside the lucent binary (library/*.xml in the
// sources), included as <include src="lucent:NAME.xml"/>. Compiled in, so it is always
// there and always readable, wherever the binary is and whatever the file-access rules.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace lucent {

inline constexpr std::string_view kLibraryPrefix = "lucent:";

// The text of library file NAME (e.g. "metals.xml"), if there is one.
std::optional<std::string_view> libraryFile(std::string_view name);
// Every library file's name, sorted.
std::vector<std::string_view> libraryFileNames();

}  // namespace lucent
