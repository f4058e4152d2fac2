// The files `lucent compare` leaves for people and scripts: report.json (every number,
// one key per line) and report.html (the two renders side by side, the heat map, the
// metrics and both renderers' times).
#pragma once

#include "image_compare.h"

#include <string>
#include <vector>

namespace lucent {

struct CompareReport {
  std::string scene;         // the Lucent scene file
  std::string povScene;      // the POV-Ray file rendered (exported or given with --pov)
  bool handWritten = false;  // --pov FILE rather than the export
  int width = 0, height = 0;
  int samples = 1;
  int maxDepth = 5;
  double minWeight = 0.0;
  std::string lucentRender;  // how Lucent rendered: "library" (the render API)
  double lucentSeconds = 0.0;
  double povraySeconds = 0.0;
  std::string povrayCommand;
  ImageMetrics metrics;
  double heatMapScale = 0.0;
  // File names inside the report's folder.
  std::string lucentImage, povrayImage, lucentLinear, povrayLinear, heatMap, povrayLog;
  std::vector<std::string> warnings;  // export warnings and comparison notes
};

std::string reportJson(const CompareReport& report);
std::string reportHtml(const CompareReport& report);

// A JSON string literal (RFC 8259 escapes).
std::string jsonString(const std::string& text);

}  // namespace lucent
