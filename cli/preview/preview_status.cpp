#include "preview_status.h"

#include "json_text.h"

#include <fmt/core.h>

namespace lucent::preview {

std::string PreviewStatus::json() const {
  std::string sliders;
  for (size_t i = 0; i < parameters.size(); ++i)
    sliders += fmt::format("{}{{\"name\":{},\"declared\":{},\"value\":{}}}", i ? "," : "",
                           jsonString(parameters[i].name), parameters[i].declared,
                           jsonString(i < values.size() ? values[i] : ""));
  return fmt::format(
      "{{\"scene\":{},\"generation\":{},\"phase\":{},\"step\":{},\"width\":{},\"height\":{},"
      "\"done\":{},\"total\":{},\"seconds\":{:.3f},\"stats\":{},\"messages\":{},"
      "\"parameters\":[{}],\"frames\":{},\"frame\":{},\"samples\":{},\"region\":{}}}",
      jsonString(scene), generation, jsonString(phase), step, width, height, done, total, seconds,
      jsonString(stats), jsonString(messages), sliders, frames, frame, samples, jsonString(region));
}

}  // namespace lucent::preview
