#include "last_image.h"

#include "app/image_output.h"
#include "render/working_gamma.h"

#include <fmt/core.h>

#include <exception>

namespace lucent::preview {

void LastImage::set(Image image, const WorkingGamma& gamma) {
  auto shared = std::make_shared<const Image>(std::move(image));
  std::lock_guard lock(mutex_);
  image_ = std::move(shared);
  gamma_ = gamma;
}

std::shared_ptr<const Image> LastImage::get() const {
  std::lock_guard lock(mutex_);
  return image_;
}

bool LastImage::save(std::string& message) const {
  std::shared_ptr<const Image> image;
  WorkingGamma gamma;
  {
    std::lock_guard lock(mutex_);
    image = image_;
    gamma = gamma_;
  }
  if (!image) {
    message = "no finished image to save yet";
    return false;
  }
  try {
    Image storage;
    writeImageFile(lightOf(*image, gamma, storage), output_);
  } catch (const std::exception& e) {
    message = e.what();
    return false;
  }
  message = fmt::format("wrote '{}' ({}x{})", output_, image->width, image->height);
  return true;
}

}  // namespace lucent::preview
