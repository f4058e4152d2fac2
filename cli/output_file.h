// Text outputs of the commands (export-pov's .pov, convert's .xml): checked before the scene
// is read, and written so that an existing file is replaced only by a complete new one.
#pragma once

#include <string>

namespace lucent::cli {

// Before the scene is read: an output that can never be written is an IoFailure now.
// `kind` names what the file should be ("a .pov file").
void checkOutputPath(const std::string& path, const std::string& kind);

// Writes through a temporary file in the same folder renamed over `path`. Messages name
// `path` and its folder, never the temporary file, which the user did not ask for.
void writeAtomically(const std::string& path, const std::string& text);

}  // namespace lucent::cli
