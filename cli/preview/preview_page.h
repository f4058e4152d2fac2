// The preview's one page: page/preview.html with page/preview.css and page/preview.js put
// into it, built into the program (no file to find at run time, nothing fetched).
#pragma once

namespace lucent::preview {

const char* previewPage();

}  // namespace lucent::preview
