// Parses a generated scene of 100,000 nodes (groups of transformed spheres, boxes and
// <use>s with named and inline materials) and builds its graph and world; prints the
// times. The target is under one second for parsing; it is reported, not asserted.
#include "lang/parser.h"
#include "scenegraph/scene_summary.h"
#include "scenegraph/world.h"

#include <fmt/core.h>

#include <chrono>
#include <ctime>
#include <string>

using namespace lucent;
using Clock = std::chrono::steady_clock;

namespace {

std::string generateScene(int groups, int perGroup) {
  std::string xml;
  xml.reserve(static_cast<size_t>(groups) * perGroup * 110);
  xml +=
      "<scene version=\"1\">\n<render width=\"320\" height=\"240\"/>\n<camera position=\"0 5 "
      "40\"/>\n";
  xml += "<param name=\"r\" value=\"0.4\"/>\n";
  for (int m = 0; m < 10; ++m)
    xml += fmt::format(
        "<material id=\"m{}\" diffuse=\"0.{} 0.5 0.5\" specular=\"0.3\" shininess=\"40\"/>\n", m,
        m);
  xml +=
      "<defs><group id=\"pair\"><sphere radius=\"0.2\"/><box min=\"-0.1 -0.1 -0.1\" max=\"0.1 0.1 "
      "0.1\"/></group></defs>\n";
  for (int g = 0; g < groups; ++g) {
    xml += fmt::format(
        "<group id=\"g{}\" material=\"m{}\" transform=\"translate({} 0 {}) rotate-y({})\">\n", g,
        g % 10, g % 40 - 20, g / 40 - 12, g % 360);
    for (int i = 1; i < perGroup; ++i) {
      switch (i % 4) {
        case 0:
          xml += fmt::format("  <sphere center=\"{} {} 0\" radius=\"$r\"/>\n", i % 10, i / 10);
          break;
        case 1:
          xml += fmt::format(
              "  <box min=\"0 0 {}\" max=\"0.5, 0.5, {}.5\" transform=\"scale(0.5) rotate(30, 1 1 "
              "0)\"/>\n",
              i, i);
          break;
        case 2:
          xml += fmt::format(
              "  <use ref=\"pair\" transform=\"translate({} 1 1)\" material=\"m{}\"/>\n", i,
              i % 10);
          break;
        default:
          xml += fmt::format(
              "  <sphere radius=\"0.3\" transform=\"translate(0 {} 0)\"><material "
              "diffuse=\"#{:02x}8040\"/></sphere>\n",
              i, i % 256);
      }
    }
    xml += "</group>\n";
  }
  xml += "</scene>\n";
  return xml;
}

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

int main() {
  const int groups = 1000, perGroup = 100;  // 1000 groups + 99,000 children = 100,000 nodes
  std::string xml = generateScene(groups, perGroup);

  // CPU time besides wall time: on a loaded machine the wall clock says little.
  auto t0 = Clock::now();
  std::clock_t c0 = std::clock();
  ParseResult r = parseSceneString(xml, "bench.xml");
  std::clock_t c1 = std::clock();
  auto t1 = Clock::now();
  if (!r.scene) {
    for (const Diagnostic& d : r.diagnostics.all()) fmt::print(stderr, "{}\n", d.str());
    return 1;
  }
  SceneCounts counts = countScene(*r.scene);
  int nodes = 0;
  for (const auto& [name, n] : counts.nodes) nodes += n;
  nodes -= 3;  // the <defs> group and its two shapes are not part of the 100,000
  fmt::print("scene text: {:.1f} MB, {} nodes, {} leaf instances, {} materials\n", xml.size() / 1e6,
             nodes, counts.instances, r.scene->materials.size());
  fmt::print("parse + graph: {:.3f} s wall, {:.3f} s CPU (target < 1 s)\n", seconds(t0, t1),
             double(c1 - c0) / CLOCKS_PER_SEC);

  auto t2 = Clock::now();
  World world(*r.scene);
  auto t3 = Clock::now();
  fmt::print("world (shapes, transforms, BVH): {:.3f} s for {} instances\n", seconds(t2, t3),
             world.leaves().size());
  return 0;
}
