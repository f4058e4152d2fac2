#include "preview_status.h"

#include "json_text.h"

#include <fmt/core.h>

namespace lucent::preview {

std::string PreviewStatus::json() const {
  return fmt::format(
      "{{\"scene\":{},\"generation\":{},\"phase\":{},\"step\":{},\"width\":{},\"height\":{},"
      "\"done\":{},\"total\":{},\"seconds\":{:.3f},\"stats\":{},\"messages\":{}}}",
      jsonString(scene), generation, jsonString(phase), step, width, height, done, total, seconds,
      jsonString(stats), jsonString(messages));
}

}  // namespace lucent::preview
