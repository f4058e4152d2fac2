// The last image a preview finished, for the page's "save" button: kept by the render loop,
// written by a request of the server's threads.
#pragma once

#include "render/image.h"
#include "scenegraph/render_settings.h"

#include <memory>
#include <mutex>
#include <string>

namespace lucent::preview {

class LastImage {
 public:
  // `output`: where save() writes (the file `lucent render` writes without -o).
  explicit LastImage(std::string output) : output_(std::move(output)) {}

  // `image` holds the scene's values; save() writes them decoded with `gamma` (its working
  // gamma), as `render` writes them.
  void set(Image image, const WorkingGamma& gamma = {});
  // The image, or null before the first one.
  std::shared_ptr<const Image> get() const;
  // Writes the image (atomically, as `render` writes its output); the message to show:
  // "wrote 'FILE' (WxH)", or why not. False when nothing was written.
  bool save(std::string& message) const;

 private:
  const std::string output_;
  mutable std::mutex mutex_;
  std::shared_ptr<const Image> image_;
  WorkingGamma gamma_;
};

}  // namespace lucent::preview
