// A tile-cost trace (what `lucent render --tile-costs FILE` writes) and the cost grids that
// bench/tile_schedule.cpp simulates: the recorded grid, a coarser one for a larger tile
// size, or a synthetic one when there is no trace.
//
//   # lucent tile costs 1
//   # image 3840 2160 tile 16 threads 1 samples 16 scene examples/five-shapes.xml
//   x0 y0 x1 y1 seconds
//   0 0 16 16 0.00123
//
// '#' lines are comments, except the header: a '#' line whose first word is `image`, `tile`,
// `threads` or `load`. It holds key/value pairs in any order (`image` takes two values,
// every other key one; unknown keys are ignored). `image`, `tile` and `threads` are
// required; `load` (seconds to load the scene) is optional; the value of an unknown key
// runs to the next known one (`image`, `tile`, `threads`, `load`, `samples`). The column line
// `x0 y0 x1 y1 seconds` is optional. Each tile line gives half-open pixel bounds on the
// grid of `tile`-sized tiles (edge tiles smaller) and the tile's wall time on `threads`
// threads; every tile of the image has exactly one line.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucent::bench {

// Costs of a grid of square tiles covering a width×height image, row-major; edge tiles
// are smaller. `cost` is seconds on `threads` threads.
struct CostGrid {
  int width = 0, height = 0, tile = 0;
  int threads = 1;
  double loadSeconds = 0.0;  // the trace's `load` key: seconds to load the scene
  bool hasLoad = false;
  std::vector<double> cost;

  int cols() const { return (width + tile - 1) / tile; }
  int rows() const { return (height + tile - 1) / tile; }
  int count() const { return cols() * rows(); }
  // Pixels of tile i (edge tiles are cut by the image border).
  long pixels(int i) const {
    const int cx = i % cols(), cy = i / cols();
    const long w = std::min(tile, width - cx * tile), h = std::min(tile, height - cy * tile);
    return w * h;
  }
  double total() const {
    double s = 0.0;
    for (double c : cost) s += c;
    return s;
  }
};

// The grid of tiles `factor` times larger: each one costs the sum of the tiles it covers.
inline CostGrid coarsen(const CostGrid& g, int factor) {
  if (factor < 1) throw std::invalid_argument("tile factor must be at least 1");
  CostGrid out = g;
  out.tile = g.tile * factor;
  out.cost.assign(size_t(out.count()), 0.0);
  for (int cy = 0; cy < g.rows(); ++cy)
    for (int cx = 0; cx < g.cols(); ++cx)
      out.cost[size_t((cy / factor) * out.cols() + cx / factor)] +=
          g.cost[size_t(cy * g.cols() + cx)];
  return out;
}

// A region of the image (fractions of width and height, half-open) whose pixels cost
// `factor` times the base cost.
struct HotRegion {
  double x0, y0, x1, y1, factor;
};

// A synthetic recording on one thread: every pixel costs `pixelSeconds`, times the factor
// of each hot region that holds it (regions multiply where they overlap). Costs are
// integrated per pixel so that a region's edge inside a tile counts only its pixels.
inline CostGrid syntheticGrid(int width, int height, int tile, double pixelSeconds,
                              const std::vector<HotRegion>& hot) {
  if (width < 1 || height < 1 || tile < 1)
    throw std::invalid_argument("synthetic image and tile sizes must be positive");
  if (!(pixelSeconds >= 0.0) || !std::isfinite(pixelSeconds))
    throw std::invalid_argument("pixel cost must be a finite number of seconds, at least 0");
  for (const HotRegion& r : hot)
    if (!(r.factor >= 0.0) || !std::isfinite(r.factor) || !(r.x0 < r.x1) || !(r.y0 < r.y1))
      throw std::invalid_argument("a hot region needs x0 < x1, y0 < y1 and a factor of at least 0");
  CostGrid g;
  g.width = width;
  g.height = height;
  g.tile = tile;
  g.threads = 1;
  g.cost.assign(size_t(g.count()), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double c = pixelSeconds;
      const double u = (x + 0.5) / width, v = (y + 0.5) / height;
      for (const HotRegion& r : hot)
        if (u >= r.x0 && u < r.x1 && v >= r.y0 && v < r.y1) c *= r.factor;
      g.cost[size_t((y / tile) * g.cols() + x / tile)] += c;
    }
  return g;
}

namespace detail {

inline std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string t; in >> t;) w.push_back(t);
  return w;
}

// A whole word as an integer or a number; false for anything else ("12x", "", "1e99" as int).
inline bool toInt(const std::string& s, long& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtol(s.c_str(), &end, 10);
  return errno == 0 && *end == '\0';
}
inline bool toNumber(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  return errno == 0 && *end == '\0' && std::isfinite(out);
}

}  // namespace detail

// Reads a trace; throws std::runtime_error "NAME:LINE: what is wrong" (or "NAME: ..." for
// what no single line shows, such as a missing tile).
inline CostGrid parseTileCosts(std::istream& in, const std::string& name) {
  using detail::toInt;
  using detail::toNumber;
  auto fail = [&](int line, const std::string& what) -> std::runtime_error {
    return std::runtime_error(name + ":" + std::to_string(line) + ": " + what);
  };
  CostGrid g;
  int headerLine = 0;
  std::vector<int> lineOf;  // the line that gave each tile, 0 while missing
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::vector<std::string> w = detail::words(text);
    if (w.empty()) continue;
    if (w[0][0] == '#') {
      // "#image ..." and "# image ..." are the same line.
      if (w[0].size() > 1) w[0] = w[0].substr(1);
      else w.erase(w.begin());
      const bool header =
          !w.empty() && (w[0] == "image" || w[0] == "tile" || w[0] == "threads" || w[0] == "load");
      if (!header) continue;
      if (headerLine)
        throw fail(line,
                   "a second header line (the first is line " + std::to_string(headerLine) + ")");
      headerLine = line;
      std::map<std::string, std::vector<std::string>> keys;
      auto known = [](const std::string& k) {
        return k == "image" || k == "tile" || k == "threads" || k == "load" || k == "samples";
      };
      for (size_t i = 0; i < w.size();) {
        const std::string key = w[i];
        size_t n = key == "image" ? 2 : 1;
        if (i + n >= w.size()) throw fail(line, "header key '" + key + "' has no value");
        // An unknown key's value (a scene path with spaces) runs to the next known key.
        if (!known(key))
          while (i + n + 1 < w.size() && !known(w[i + n + 1])) ++n;
        if (keys.count(key)) throw fail(line, "header key '" + key + "' given twice");
        keys[key] = std::vector<std::string>(w.begin() + long(i + 1), w.begin() + long(i + 1 + n));
        i += 1 + n;
      }
      auto positive = [&](const std::string& key, size_t k) {
        auto it = keys.find(key);
        if (it == keys.end()) throw fail(line, "the header has no '" + key + "' key");
        long v = 0;
        if (!toInt(it->second[k], v) || v < 1 || v > 1000000)
          throw fail(line, "header key '" + key +
                               "' needs a positive integer (at most 1000000), got '" +
                               it->second[k] + "'");
        return int(v);
      };
      g.width = positive("image", 0);
      g.height = positive("image", 1);
      g.tile = positive("tile", 0);
      g.threads = positive("threads", 0);
      if (auto it = keys.find("load"); it != keys.end()) {
        if (!toNumber(it->second[0], g.loadSeconds) || g.loadSeconds < 0)
          throw fail(line,
                     "header key 'load' needs seconds (at least 0), got '" + it->second[0] + "'");
        g.hasLoad = true;
      }
      if (long(g.cols()) * g.rows() > 10000000L) throw fail(line, "more than 10 million tiles");
      g.cost.assign(size_t(g.count()), 0.0);
      lineOf.assign(size_t(g.count()), 0);
      continue;
    }
    if (w[0] == "x0") {
      if (w != std::vector<std::string>{"x0", "y0", "x1", "y1", "seconds"})
        throw fail(line, "the column line must read 'x0 y0 x1 y1 seconds'");
      continue;
    }
    if (!headerLine)
      throw fail(line, "a tile line before the '# image W H tile T threads N' header");
    long b[4];
    double s = 0;
    if (w.size() != 5 || !toInt(w[0], b[0]) || !toInt(w[1], b[1]) || !toInt(w[2], b[2]) ||
        !toInt(w[3], b[3]) || !toNumber(w[4], s))
      throw fail(line,
                 "expected 'x0 y0 x1 y1 seconds' (four integers and a number), got '" + text + "'");
    if (s < 0) throw fail(line, "negative seconds");
    const long x0 = b[0], y0 = b[1], x1 = b[2], y1 = b[3];
    if (x0 < 0 || y0 < 0 || x0 >= g.width || y0 >= g.height || x0 % g.tile || y0 % g.tile ||
        x1 != std::min<long>(x0 + g.tile, g.width) || y1 != std::min<long>(y0 + g.tile, g.height))
      throw fail(line, "bounds " + w[0] + " " + w[1] + " " + w[2] + " " + w[3] +
                           " are not a tile of the " + std::to_string(g.tile) +
                           "-pixel grid of the " + std::to_string(g.width) + "x" +
                           std::to_string(g.height) + " image");
    const size_t i = size_t((y0 / g.tile) * g.cols() + x0 / g.tile);
    if (lineOf[i])
      throw fail(line, "tile " + w[0] + " " + w[1] + " already given on line " +
                           std::to_string(lineOf[i]));
    lineOf[i] = line;
    g.cost[i] = s;
  }
  if (!headerLine)
    throw std::runtime_error(name + ": no '# image W H tile T threads N' header line");
  const long missing = std::count(lineOf.begin(), lineOf.end(), 0);
  if (missing) {
    const size_t i = size_t(std::find(lineOf.begin(), lineOf.end(), 0) - lineOf.begin());
    throw std::runtime_error(name + ": " + std::to_string(missing) + " of " +
                             std::to_string(g.count()) + " tiles have no line, the first at " +
                             std::to_string((long(i) % g.cols()) * g.tile) + " " +
                             std::to_string((long(i) / g.cols()) * g.tile));
  }
  return g;
}

}  // namespace lucent::bench
