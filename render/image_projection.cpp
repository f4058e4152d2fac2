#include "image_projection.h"

#include <cmath>
#include <type_traits>

namespace lucent {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
// POV-Ray nudges every image coordinate by its EPSILON before wrapping it.
constexpr double kNudge = 1e-10;

// x wrapped into [0, limit), as POV-Ray's wrap (fmod, then negatives moved up).
double wrap(double x, double limit) {
  double r = std::fmod(x, limit);
  if (r < 0.0) r += limit;
  return r >= limit ? 0.0 : r;
}

// The angle of (x, z) from +x towards +z, in turns: [0, 1); nothing on the y axis.
std::optional<double> longitude(double x, double z) {
  const double len = std::sqrt(x * x + z * z);
  if (len == 0.0) return std::nullopt;
  double theta;
  if (z == 0.0) theta = x > 0.0 ? 0.0 : kPi;
  else theta = z < 0.0 ? kTwoPi - std::acos(x / len) : std::acos(x / len);
  return theta / kTwoPi;
}

// The image coordinates (u across, v up, in pixels) of a point before POV-Ray's nudge and
// wrap; nothing where the projection gives none.
std::optional<Vec2> mapped(ImageProjection projection, const Vec3& q, double w, double h,
                           bool once) {
  switch (projection) {
    case ImageProjection::uv:
    case ImageProjection::planar:
      if (once && (q.x < 0.0 || q.x > 1.0 || q.y < 0.0 || q.y > 1.0)) return std::nullopt;
      return Vec2(std::fmod(q.x * w, w), std::fmod(q.y * h, h));
    case ImageProjection::spherical: {
      const double len = glm::length(q);
      if (len == 0.0) return std::nullopt;
      const Vec3 d = q / len;
      const double phi = 0.5 + std::asin(d.y) / kPi;
      const double theta = longitude(d.x, d.z).value_or(0.0);  // a pole: any longitude
      return Vec2(theta * w, phi * h);
    }
    case ImageProjection::cylindrical: {
      if (once && (q.y < 0.0 || q.y > 1.0)) return std::nullopt;
      const double v = std::fmod(q.y * h, h);
      const double len = glm::length(q);
      if (len == 0.0) return std::nullopt;
      const auto theta = longitude(q.x / len, q.z / len);
      if (!theta) return std::nullopt;
      return Vec2(*theta * w, v);
    }
    case ImageProjection::torus: {
      const auto theta = longitude(q.x, q.z);
      if (!theta) return std::nullopt;
      // Into the torus' cross-section: distance out from the tube's centre circle (major
      // radius 1), and up.
      const double x = std::sqrt(q.x * q.x + q.z * q.z) - 1.0;
      const double len = std::sqrt(x * x + q.y * q.y);
      if (len == 0.0) return std::nullopt;
      double phi = std::acos(-x / len);
      if (q.y > 0.0) phi = kTwoPi - phi;
      // POV-Ray negates the longitude twice: u = −(−θ)·w.
      return Vec2(*theta * w, phi / kTwoPi * h);
    }
  }
  return std::nullopt;
}

// POV-Ray's last step: the nudge, the `once` bounds, and the wrap (rows counted down).
std::optional<Vec2> onImage(Vec2 uv, int width, int height, bool once) {
  uv += Vec2(kNudge);
  if (once && (uv.x >= width || uv.y >= height || uv.x < 0.0 || uv.y < 0.0)) return std::nullopt;
  return Vec2(wrap(uv.x, width), wrap(-uv.y, height));
}

// The pixel at (x, y), wrapped round, or for a `once` image clamped to its edge: a colour
// of an Image, a value of an ImageValueGrid.
template <class Grid>
auto pixel(const Grid& image, double x, double y, bool once) {
  int ix, iy;
  if (once) {
    ix = x < 0.0 ? 0 : x >= image.width ? image.width - 1 : static_cast<int>(x);
    iy = y < 0.0 ? 0 : y >= image.height ? image.height - 1 : static_cast<int>(y);
  } else {
    ix = static_cast<int>(wrap(x, image.width));
    iy = static_cast<int>(wrap(y, image.height));
  }
  return image.at(ix, iy);
}

// Blends are summed in double precision, as POV-Ray's.
glm::dvec3 precise(const Color& c) { return glm::dvec3(c); }
glm::dvec2 precise(const glm::vec2& v) { return glm::dvec2(v); }
double precise(float v) { return v; }
double precise(double v) { return v; }

// Catmull-Rom weights of the four pixels around fraction x (POV-Ray's cubic).
void cubicWeights(double x, double w[4]) {
  const double p = x - static_cast<int>(x), q = 1.0 - p;
  w[0] = -0.5 * p * q * q;
  w[1] = 0.5 * q * (q * (3.0 * p + 1.0) + 1.0);
  w[2] = 0.5 * p * (p * (3.0 * q + 1.0) + 1.0);
  w[3] = -0.5 * q * p * p;
}

template <class Grid>
auto bicubic(const Grid& image, double x, double y, bool once) {
  x += 0.5;
  y += 0.5;
  const int ix = static_cast<int>(x), iy = static_cast<int>(y);
  double wx[4], wy[4];
  cubicWeights(x, wx);
  cubicWeights(y, wy);
  decltype(precise(pixel(image, 0, 0, once))) sum(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      sum += precise(pixel(image, ix + i - 2, iy + j - 2, once)) * (wx[i] * wy[j]);
  return sum;
}

// The four pixels whose centres surround the point, weighted by area (bilinear) or by
// inverse squared distance (normalized).
template <class Grid>
auto fourCorners(const Grid& image, double x, double y, bool once, bool normalized) {
  x += 0.5;
  y += 0.5;
  const int ix = static_cast<int>(x), iy = static_cast<int>(y);
  const double p = x - ix, q = y - iy;
  double f[4];
  if (normalized) {
    const double w[4] = {1.0 / ((1 - p) * (1 - p) + (1 - q) * (1 - q)),
                         1.0 / (p * p + (1 - q) * (1 - q)), 1.0 / ((1 - p) * (1 - p) + q * q),
                         1.0 / (p * p + q * q)};
    const double total = w[0] + w[1] + w[2] + w[3];
    // On a pixel centre one weight is infinite (POV-Ray's would be NaN): that pixel alone.
    for (int i = 0; i < 4; ++i)
      f[i] = std::isfinite(total) ? w[i] / total : std::isinf(w[i]) ? 1.0 : 0.0;
  } else {
    f[0] = p * q;
    f[1] = (1 - p) * q;
    f[2] = p * (1 - q);
    f[3] = (1 - p) * (1 - q);
  }
  return precise(pixel(image, ix, iy, once)) * f[0] +
         precise(pixel(image, ix - 1, iy, once)) * f[1] +
         precise(pixel(image, ix, iy - 1, once)) * f[2] +
         precise(pixel(image, ix - 1, iy - 1, once)) * f[3];
}

}  // namespace

std::optional<Vec2> projectToImage(ImageProjection projection, const Vec3& q, int width, int height,
                                   bool once) {
  const auto uv = mapped(projection, q, width, height, once);
  if (!uv) return std::nullopt;
  return onImage(*uv, width, height, once);
}

std::optional<Vec2> uvToImage(const Vec2& uv, const Vec2& scale, int width, int height, bool once) {
  return projectToImage(ImageProjection::planar, Vec3(uv / scale, 0.0), width, height, once);
}

namespace {

// The pixel or the blend of pixels at `xy`, in single precision as POV-Ray keeps it.
template <class Grid>
auto sampled(const Grid& image, const Vec2& xy, ImageInterpolation interpolation, bool once) {
  using Single = std::decay_t<decltype(pixel(image, 0, 0, once))>;
  switch (interpolation) {
    case ImageInterpolation::none:
      break;
    case ImageInterpolation::bilinear:
      return Single(fourCorners(image, xy.x, xy.y, once, false));
    case ImageInterpolation::normalized:
      return Single(fourCorners(image, xy.x, xy.y, once, true));
    case ImageInterpolation::bicubic:
      return Single(bicubic(image, xy.x, xy.y, once));
  }
  return Single(pixel(image, xy.x, xy.y, once));
}

}  // namespace

PigmentColor sampleImage(const Image& image, const Vec2& xy, ImageInterpolation interpolation,
                         bool once, const FilterTransmit& all) {
  return {sampled(image, xy, interpolation, once), all};
}

namespace {

// An image's filter and transmit by pixel, as the blends read a grid: a palette entry's own,
// else the image's, with the pixel's 1 − alpha added to the transmit (use-alpha).
struct PixelFilterTransmit {
  const ImageValueGrid* palette;
  const ImageValueGrid* alpha;
  const ImageTexture& image;
  int width, height;
  glm::vec2 at(int x, int y) const {
    const size_t i = static_cast<size_t>(y) * width + x;
    FilterTransmit ft = image.all;
    std::optional<float> ownTransmit;
    if (palette)
      for (const PaletteEntryFT& e : image.palette)
        if (e.index == palette->indices[i]) {
          ft.filter = e.filter.value_or(ft.filter);
          ownTransmit = e.transmit ? e.transmit : ownTransmit;
        }
    ft.transmit = ownTransmit.value_or(ft.transmit + (alpha ? alpha->values[i] : 0.0f));
    return {ft.filter, ft.transmit};
  }
};

bool fits(const ImageValueGrid* grid, const Image& pixels) {
  return grid && grid->width == pixels.width && grid->height == pixels.height;
}

}  // namespace

PigmentColor sampleImageTexture(const Image& pixels, const ImageTexture& image, const Vec2& xy) {
  PigmentColor c = sampleImage(pixels, xy, image.interpolation, image.once, image.all);
  const ImageValueGrid* palette = image.palette.empty() ? nullptr : image.paletteIndices.get();
  const ImageValueGrid* alpha = image.alphaTransmit.get();
  if (!fits(palette, pixels)) palette = nullptr;
  if (!fits(alpha, pixels)) alpha = nullptr;
  if (!palette && !alpha) return c;
  // POV-Ray blends the pixels' filter and transmit as it blends their colours.
  const glm::vec2 ft =
      sampled(PixelFilterTransmit{palette, alpha, image, pixels.width, pixels.height}, xy,
              image.interpolation, image.once);
  c.ft = {ft.x, ft.y};
  return c;
}

float sampleImageValue(const ImageValueGrid& grid, const Vec2& xy, ImageInterpolation interpolation,
                       bool once) {
  return sampled(grid, xy, interpolation, once);
}

namespace {

// A grid's palette indices as POV-Ray hands them to its blends: -1 for a pixel of an image
// without a palette.
struct IndexView {
  const ImageValueGrid& grid;
  int width, height;
  double at(int x, int y) const {
    return grid.indices.empty() ? -1.0 : grid.indices[static_cast<size_t>(y) * width + x];
  }
};

}  // namespace

int samplePaletteIndex(const ImageValueGrid& grid, const Vec2& xy, ImageInterpolation interpolation,
                       bool once) {
  return static_cast<int>(
      sampled(IndexView{grid, grid.width, grid.height}, xy, interpolation, once));
}

int sampleImageIndex(const ImageValueGrid& grid, const Vec2& xy, ImageInterpolation interpolation,
                     bool once) {
  const int index = samplePaletteIndex(grid, xy, interpolation, once);
  if (index != -1) return index;
  const double red = sampleImageValue(grid, xy, interpolation, once);
  return static_cast<int>(red * 255.0);
}

}  // namespace lucent
