#include "adaptive_centre_sampler.h"

#include "pixel_passes.h"

#include <algorithm>
#include <vector>

namespace lucent {

namespace {

// Largest per-channel difference of two linear colours, the adaptive threshold's measure.
float colorDifference(const Color& a, const Color& b) { return maxComponent(glm::abs(a - b)); }

// The samples a refined pixel has taken so far: their sum and the range of their values
// (the centre sample included in the range).
struct PixelRefinement {
  Color sum{0.0f}, lowest{0.0f}, highest{0.0f};
  int taken = 0;
  bool disagrees(float threshold) const { return maxComponent(highest - lowest) > threshold; }
};

// One rectangle's refinement: the centres of `area` (the rectangle and its margin), which
// of its pixels are still refined, and the samples each has taken.
class CentreRefinement {
 public:
  CentreRefinement(const CameraSamples& camera, const PixelRect& rect, const PixelRect& whole,
                   int margin, float threshold)
      : camera_(camera),
        rect_(rect),
        whole_(whole),
        area_(rect.grown(margin, whole)),
        margin_(margin),
        threshold_(threshold),
        centres_(static_cast<size_t>(area_.pixels())),
        refine_(centres_.size()),
        active_(centres_.size(), 0),
        next_(centres_.size(), 0) {}

  void traceCentres(PixelPasses& passes);
  void writeCentres(Image& out) const;
  // Marks the pixels to refine: those whose centre differs from a neighbour's.
  void markEdges();
  // Stage k (from 1): samples up to `stage` for the active pixels the stage still reaches.
  void refine(PixelPasses& passes, int stage, int k);
  // Decides which pixels go on after stage k; false when none does.
  bool settle(int k);
  void writeRefined(Image& out) const;

 private:
  size_t at(int x, int y) const {
    return static_cast<size_t>(y - area_.y0) * area_.width() + (x - area_.x0);
  }
  // How far (in pixels, the chessboard distance) (x, y) lies outside the rectangle.
  int distance(int x, int y) const {
    return std::max({rect_.x0 - x, x - (rect_.x1 - 1), rect_.y0 - y, y - (rect_.y1 - 1), 0});
  }
  // Whether (x, y) still decides a pixel of the rectangle when decisions reach `reach`
  // pixels further (the rectangle's pixels always do).
  bool reaches(int x, int y, int reach) const {
    const int d = distance(x, y);
    return d == 0 || d <= reach;
  }
  bool differ(int x, int y, int nx, int ny) const {
    return colorDifference(centres_[at(x, y)], centres_[at(nx, ny)]) > threshold_;
  }
  // Calls f(nx, ny) for each of the eight neighbours of (x, y) inside the image (not only
  // inside `area`: a pixel sees the same neighbours in every rectangle): a diagonal edge
  // shows first between diagonal neighbours.
  template <class F>
  void forNeighbours(int x, int y, F&& f) const {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx || dy) && whole_.contains(nx, ny)) f(nx, ny);
      }
  }
  // Traces samples r.taken .. upTo-1 of pixel (x, y) into r.
  void addSamples(int x, int y, int upTo, PixelRefinement& r, TraceContext& context) const;

  const CameraSamples& camera_;
  const PixelRect rect_, whole_, area_;
  const int margin_;
  const float threshold_;
  std::vector<Color> centres_;
  std::vector<PixelRefinement> refine_;
  std::vector<char> active_, next_;
};

void CentreRefinement::traceCentres(PixelPasses& passes) {
  passes.forEachPixel(area_, [&](int x, int y, TraceContext& context) {
    centres_[at(x, y)] = camera_.sample(x, y, 0, 1, context);
  });
}

void CentreRefinement::writeCentres(Image& out) const {
  for (int y = rect_.y0; y < rect_.y1; ++y)
    for (int x = rect_.x0; x < rect_.x1; ++x)
      out.at(x - rect_.x0, y - rect_.y0) = centres_[at(x, y)];
}

void CentreRefinement::markEdges() {
  for (int y = area_.y0; y < area_.y1; ++y)
    for (int x = area_.x0; x < area_.x1; ++x) {
      PixelRefinement& r = refine_[at(x, y)];
      r.lowest = r.highest = centres_[at(x, y)];
      // A pixel at the margin's edge is never refined (its neighbours are not all known).
      if (distance(x, y) < margin_)
        forNeighbours(x, y, [&](int nx, int ny) { active_[at(x, y)] |= differ(x, y, nx, ny); });
    }
}

void CentreRefinement::addSamples(int x, int y, int upTo, PixelRefinement& r,
                                  TraceContext& context) const {
  const int count = camera_.samples();
  for (; r.taken < upTo; ++r.taken) {
    const Color c = camera_.sample(x, y, r.taken, count, context);
    r.sum += c;  // summed in k order, so a pixel that takes all samples equals the fixed sampler's
    r.lowest = glm::min(r.lowest, c);
    r.highest = glm::max(r.highest, c);
  }
}

// Stage k (from 1) refines the pixels within margin - k of the rectangle: only those still
// decide a pixel of the rectangle. Only the first stage counts as work: the later ones
// refine a share of the pixels that cannot be known in advance.
void CentreRefinement::refine(PixelPasses& passes, int stage, int k) {
  const int reach = margin_ - k;
  passes.forEachPixel(
      area_,
      [&](int x, int y, TraceContext& context) {
        if (active_[at(x, y)] && reaches(x, y, reach))
          addSamples(x, y, stage, refine_[at(x, y)], context);
      },
      k == 1);
}

// After a stage a pixel stops when its samples (and its centre) agree within the threshold
// AND every neighbour whose centre differs from its own shows that disagreement inside
// itself: the edge between the two centres is then in the neighbour. Otherwise the edge may
// be in this pixel where its samples so far missed it (a silhouette cutting off a corner
// that no sample fell in), so both go on.
bool CentreRefinement::settle(int k) {
  const int reach = margin_ - k;
  bool any = false;
  for (int y = area_.y0; y < area_.y1; ++y)
    for (int x = area_.x0; x < area_.x1; ++x) {
      const size_t i = at(x, y);
      next_[i] = 0;
      if (!active_[i] || !reaches(x, y, reach - 1)) continue;
      bool settled = !refine_[i].disagrees(threshold_);
      forNeighbours(x, y, [&](int nx, int ny) {
        if (settled && differ(x, y, nx, ny) && !refine_[at(nx, ny)].disagrees(threshold_))
          settled = false;
      });
      next_[i] = !settled;
      any |= !settled;
    }
  active_.swap(next_);
  return any;
}

void CentreRefinement::writeRefined(Image& out) const {
  for (int y = rect_.y0; y < rect_.y1; ++y)
    for (int x = rect_.x0; x < rect_.x1; ++x)
      if (const PixelRefinement& r = refine_[at(x, y)]; r.taken > 0)
        out.at(x - rect_.x0, y - rect_.y0) = r.sum / static_cast<float>(r.taken);
}

}  // namespace

int AdaptiveCentreSampler::margin(int samples) {
  int stages = 1;
  for (int stage = std::min(kFirstStage, samples); stage < samples;
       stage = std::min(2 * stage, samples))
    ++stages;
  return stages;
}

uint64_t AdaptiveCentreSampler::work(const PixelRect& rect) const {
  const PixelRect area = rect.grown(margin(camera_.samples()), wholeImage(width_, height_));
  return 2 * static_cast<uint64_t>(area.pixels());
}

void AdaptiveCentreSampler::render(const PixelRect& rect, PixelPasses& passes, Image& out) const {
  const int samples = camera_.samples();
  CentreRefinement refinement(camera_, rect, wholeImage(width_, height_), margin(samples),
                              threshold_);
  refinement.traceCentres(passes);
  refinement.writeCentres(out);
  if (passes.cancelled()) return;
  refinement.markEdges();
  for (int stage = std::min(kFirstStage, samples), k = 1;;
       stage = std::min(2 * stage, samples), ++k) {
    refinement.refine(passes, stage, k);
    if (passes.cancelled() || stage == samples) break;
    if (!refinement.settle(k)) break;
  }
  refinement.writeRefined(out);
}

}  // namespace lucent
