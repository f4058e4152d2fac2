// The command line of `lucent compare` for what a preview renders (--compare): the same
// scene, options, -D values (the sliders' too) and image size.
#pragma once

#include "commands.h"

#include <string>
#include <vector>

namespace lucent::preview {

// Without "compare" and -o; `width` x `height`: the image the preview rendered.
std::vector<std::string> compareArguments(const cli::PreviewOptions& options,
                                          const cli::CommonOptions& common, int width, int height);

}  // namespace lucent::preview
