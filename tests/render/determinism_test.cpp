// The image is the same bit for bit whatever the thread count and from run to run.
#include "scene_builder.h"

#include "render/renderer.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("the same image bit for bit with 1 and 2 threads and from run to run",
          "[render][determinism]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  RenderControl one, two;
  one.threads = 1;
  two.threads = 2;
  RenderResult a = renderer.render(one);
  RenderResult b = renderer.render(two);
  RenderResult c = renderer.render(two);
  CHECK(sameBits(a.image, b.image));
  CHECK(sameBits(b.image, c.image));
  // The statistics do not depend on the threads either.
  CHECK(a.stats.rays() == b.stats.rays());
  CHECK(a.stats.queries == b.stats.queries);
  // And the image is not trivially uniform: the test would otherwise prove nothing.
  float lo = 1e9f, hi = -1e9f;
  for (const Color& p : a.image.pixels) {
    lo = std::min(lo, p.r);
    hi = std::max(hi, p.r);
  }
  CHECK(hi - lo > 0.5f);
}

TEST_CASE("a cancelled render stops early and says so", "[render][determinism]") {
  Scene scene;
  buildBusyScene(scene);
  World world(scene);
  Renderer renderer(world, scene.cameras[0]);
  std::atomic<bool> cancel{true};
  RenderControl control;
  control.cancel = &cancel;
  RenderResult r = renderer.render(control);
  CHECK(r.cancelled);
  CHECK(r.stats.primary == 0);
}

TEST_CASE("adaptive supersampling refines only pixels that differ from a neighbour",
          "[render][determinism]") {
  Scene scene;
  buildBusyScene(scene);
  scene.render.samples = 16;
  scene.render.adaptive = 0.0;
  World world(scene);
  Renderer full(world, scene.cameras[0]);
  RenderResult all = full.render();
  const float threshold = 0.05f;
  scene.render.adaptive = threshold;
  Renderer adaptive(world, scene.cameras[0]);
  RenderResult some = adaptive.render();
  const int w = scene.render.width, h = scene.render.height;

  // Fewer primary rays than supersampling every pixel.
  CHECK(some.stats.primary < all.stats.primary);
  Image centres(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      TraceContext s;
      centres.at(x, y) = adaptive.renderSample(x, y, 0, 1, s);
    }
  int centreOnly = 0, stopped = 0, allSamples = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool differs = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = x + dx, ny = y + dy;
          if (nx >= 0 && nx < w && ny >= 0 && ny < h &&
              maxComponent(glm::abs(centres.at(x, y) - centres.at(nx, ny))) > threshold)
            differs = true;
        }
      const Color got = some.image.at(x, y);
      if (!differs) {
        // A pixel like all its neighbours keeps its centre sample.
        CHECK(got == centres.at(x, y));
        ++centreOnly;
        continue;
      }
      // A refined pixel is the mean of the first n of its 16 samples, n a stage (6, 12, 16),
      // summed in order; it stops early only where those samples and the centre agree.
      Color sum(0.0f), lo = centres.at(x, y), hi = lo;
      bool matched = false;
      for (int k = 0; k < 16 && !matched; ++k) {
        TraceContext s;
        Color c = adaptive.renderSample(x, y, k, 16, s);
        sum += c;
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
        const int n = k + 1;
        if ((n == 6 || n == 12) && got == sum / float(n)) {
          CHECK(maxComponent(hi - lo) <= threshold);
          // ... and where every neighbour whose centre differs shows the edge inside
          // itself: its centre and first n samples disagree.
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              int nx = x + dx, ny = y + dy;
              if ((dx == 0 && dy == 0) || nx < 0 || nx >= w || ny < 0 || ny >= h ||
                  maxComponent(glm::abs(centres.at(x, y) - centres.at(nx, ny))) <= threshold)
                continue;
              Color nlo = centres.at(nx, ny), nhi = nlo;
              for (int j = 0; j < n; ++j) {
                TraceContext s2;
                Color c2 = adaptive.renderSample(nx, ny, j, 16, s2);
                nlo = glm::min(nlo, c2);
                nhi = glm::max(nhi, c2);
              }
              CHECK(maxComponent(nhi - nlo) > threshold);
            }
          matched = true;
          ++stopped;
        } else if (n == 16) {
          CHECK(got == all.image.at(x, y));  // all samples: the full render's pixel
          CHECK(got == sum / 16.0f);
          matched = true;
          ++allSamples;
        }
      }
      CHECK(matched);
    }
  // The busy scene has flat regions, smooth shading inside refined pixels and hard edges.
  CHECK(centreOnly > 100);
  CHECK(stopped > 20);
  CHECK(allSamples > 20);
}
