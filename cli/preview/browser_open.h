// --open: the desktop's browser on the preview's address (xdg-open).
#pragma once

#include <string>

namespace lucent::preview {

// Starts `xdg-open url` and does not wait for it; a warning on stderr when it cannot start.
void openInBrowser(const std::string& url);

}  // namespace lucent::preview
