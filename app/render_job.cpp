#include "render_job.h"

#include <algorithm>

namespace lucent {

RenderJob::RenderJob(const RenderSettings& settings, const PixelRect& area, int tileSize, int frame,
                     double loadSeconds)
    : settings_(settings),
      area_(area),
      tileSize_(tileSize),
      frame_(frame),
      loadSeconds_(loadSeconds),
      tiles_(tilesOf(area, tileSize)),
      taken_(tiles_.size(), 0),
      image_(area.width(), area.height()) {}

void RenderJob::place(const PixelRect& t, const Image& pixels) {
  for (int y = 0; y < t.height(); ++y)
    std::copy_n(&pixels.at(0, y), t.width(), &image_.at(t.x0 - area_.x0, t.y0 - area_.y0 + y));
}

Image RenderJob::tilePixels(size_t index) const {
  const PixelRect& t = tiles_[index];
  Image pixels(t.width(), t.height());
  for (int y = 0; y < t.height(); ++y)
    std::copy_n(&image_.at(t.x0 - area_.x0, t.y0 - area_.y0 + y), t.width(), &pixels.at(0, y));
  return pixels;
}

size_t RenderJob::takeFinished(const std::vector<std::pair<PixelRect, Image>>& finished) {
  size_t taken = 0;
  for (const auto& [rect, pixels] : finished)
    for (size_t i = 0; i < tiles_.size(); ++i)
      if (tiles_[i] == rect && !taken_[i]) {
        place(rect, pixels);
        taken_[i] = 1;
        ++taken;
      }
  return taken;
}

TileRenderResult RenderJob::render(const Renderer& renderer, const RenderControl& control,
                                   const TileRunner& runner) {
  const bool oneAtATime =
      std::any_of(observers_.begin(), observers_.end(),
                  [](const RenderObserver* o) { return o->wantsTilesOneAtATime(); });
  const TileFinished finished = [&](size_t i, const RenderResult& tile) {
    place(tiles_[i], tile.image);
    for (RenderObserver* o : observers_) o->tileFinished(*this, i, tile);
  };
  const TileRenderResult result =
      runner ? runner(renderer, tiles_, taken_, control, oneAtATime, finished)
             : renderTiles(renderer, tiles_, taken_, control, oneAtATime, finished);
  for (RenderObserver* o : observers_) o->jobEnded(*this, result);
  return result;
}

}  // namespace lucent
