// A whole POV-Ray file through the language core, for the command line until the scene
// reader exists: every directive is done, and the first scene item is refused with
// "'sphere' is not read yet" at its place.
#pragma once

#include "options.h"
#include "token_stream.h"

#include <filesystem>

namespace lucent::sdl {

// The item reader that reads nothing: it refuses every scene item, where it starts.
class RefusingItemReader : public ItemReader {
 public:
  ItemPtr read(const Token& t, TokenStream& in) override;
};

// Evaluates the file at `path`; throws SdlError at the first error or scene item.
void evaluateFile(const std::filesystem::path& path, const Options& options);

// The same for `text`, named `name`, lying in `folder` (for tests).
void evaluateText(const std::string& name, const std::string& text,
                  const std::filesystem::path& folder, const Options& options);

}  // namespace lucent::sdl
