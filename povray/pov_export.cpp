#include "pov_export.h"

#include "pov_camera.h"
#include "pov_fog.h"
#include "pov_geometry.h"
#include "pov_lights.h"
#include "pov_materials.h"
#include "pov_patterns.h"
#include "pov_rainbow.h"
#include "pov_runner.h"
#include "pov_wave_sources.h"

#include "scenegraph/overloaded.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace lucent {

namespace {

// POV-Ray's MAX_TRACE_LEVEL_LIMIT: larger max_trace_level values are refused.
constexpr int kPovMaxTraceLevel = 256;

void writeSettings(const RenderSettings& r, PovWriter& out, PovIssues& issues) {
  int depth = r.maxDepth;
  if (depth > kPovMaxTraceLevel) {
    issues.warning(r.loc, fmt::format("render: max-depth {} exceeds POV-Ray's limit of {}",
                                      r.maxDepth, kPovMaxTraceLevel));
    depth = kPovMaxTraceLevel;
  }
  if (r.epsilon)
    issues.warning(r.loc, fmt::format("render: epsilon {} has no POV-Ray equivalent (POV-Ray "
                                      "ignores hits closer than its own fixed tolerances)",
                                      *r.epsilon));
  out.open("global_settings");
  // Colours are linear: with assumed_gamma 1.0 POV-Ray neither decodes nor re-encodes them
  // before its file output gamma. A working gamma is POV-Ray's assumed_gamma itself.
  const WorkingGamma& gamma = r.workingGamma;
  out.line(gamma.srgb
               ? std::string("assumed_gamma srgb")
               : "assumed_gamma " + (gamma.linear() ? std::string("1.0") : povNumber(gamma.power)));
  // Primary ray = level 1 in both; a ray beyond the limit is black in both.
  out.line(fmt::format("max_trace_level {}", depth));
  out.line("adc_bailout " + povNumber(r.minWeight));
  out.line("ambient_light " + povRgb(r.ambient));
  out.close();
  out.line("background { " + povRgb(r.background) + " }");
}

}  // namespace

bool PovExport::ok() const {
  for (const PovIssue& i : issues)
    if (i.error) return false;
  return true;
}

PovExport exportPov(const Scene& scene, const PovExportOptions& options) {
  PovIssues issues;
  PovExport result;
  const Camera* camera = scene.findCamera(options.camera);
  if (!camera) {
    issues.error(SourceLoc{scene.file}, options.camera.empty()
                                            ? "the scene has no <camera>"
                                            : fmt::format("no camera named '{}'", options.camera));
    result.issues = issues.all();
    return result;
  }
  const RenderSettings& r = scene.render;

  PovWriter out;
  out.line(fmt::format("// {} exported by Lucent as a POV-Ray 3.7 scene.",
                       std::filesystem::path(scene.file).filename().string()));
  if (r.adaptiveMode == AdaptiveMode::Corners) {
    // Lucent's corners mode is POV-Ray's method 2 without jitter: the same image.
    out.line(
        fmt::format("// Render: povray +I<this file> +W{} +H{} +AM2 {} -J +R{}   (+FN writes "
                    "sRGB, File_Gamma=1.0 linear)",
                    r.width, r.height, cornerThresholdFlag(r.adaptive), r.adaptiveDepth));
    if (r.adaptive > 1.0)
      issues.warning(r.loc, fmt::format("render: adaptive {} exceeds 1, where POV-Ray clips its "
                                        "antialiasing threshold",
                                        r.adaptive));
  } else {
    out.line(
        fmt::format("// Render: povray +I<this file> +W{} +H{} -A   (+FN writes sRGB, "
                    "File_Gamma=1.0 linear)",
                    r.width, r.height));
  }
  if (r.samples > 1 && r.adaptiveMode != AdaptiveMode::Corners)
    // Sampling is a command-line matter in POV-Ray; its grid is not Lucent's Halton set.
    out.line(
        fmt::format("// Lucent takes {} samples per pixel at Halton offsets; the closest "
                    "POV-Ray has is +A0.0 -J +AM1 +R{}",
                    r.samples, std::max(2, static_cast<int>(std::lround(std::sqrt(r.samples))))));
  // Without #version POV-Ray 3.7 applies the 3.62 rules (opacity, gamma): mandatory.
  out.line("#version 3.7;");
  out.blank();
  writeSettings(r, out, issues);
  for (const Fog& fog : scene.fogs) writeFog(fog, out, issues);
  for (const Rainbow& rainbow : scene.rainbows) writeRainbow(rainbow, out, issues);
  out.blank();
  writeCamera(*camera, r, out, issues);
  out.blank();
  if (scene.sky) {
    // The pigment is evaluated at the ray direction carried through the inverse of the
    // sky's transform, as Lucent's <sky>.
    // Its layers in order: POV-Ray's sky_sphere also puts the last pigment on top.
    if (scene.sky->layering == SkyLayering::pov36 && scene.sky->layers.size() > 1)
      issues.warning(scene.sky->loc,
                     "sky: layering=\"pov-3.6\" is POV-Ray's only for scenes of #version 3.6 "
                     "and earlier; the exported scene is 3.7's, which layers by its own rule");
    out.open("sky_sphere");
    for (const Texture& layer : scene.sky->layers) {
      std::visit(
          Overloaded{
              [&](const PatternTexture& t) { writePatternPigment(t, Vec3(1.0), 0.0, 0.0, out); },
              [&](const CheckerTexture& t) { writeCheckerPigment(t, Vec3(1.0), 0.0, 0.0, out); },
              [&](const HexagonTexture& t) { writeHexagonPigment(t, Vec3(1.0), 0.0, 0.0, out); },
              [&](const BrickTexture& t) { writeBrickPigment(t, Vec3(1.0), 0.0, 0.0, out); },
              [&](const AverageTexture& t) { writeAveragePigment(t, Vec3(1.0), 0.0, 0.0, out); },
              [](const auto&) {}},  // the parser takes no other layer
          layer);
    }
    const Mat4 worldFromSky = glm::inverse(scene.sky->skyFromWorld);
    if (worldFromSky != Mat4(1.0)) out.line(povMatrix(worldFromSky));
    out.close();
    out.blank();
  }

  PovMaterials materials(scene.materials, issues);
  PovCameraFrame frame = povCameraFrame(*camera);
  PovGeometry geometry(scene, materials, frame.location, issues);
  PovWriter declarations, objects, objectPatterns;
  geometry.writeObjectPatterns(objectPatterns);
  geometry.write(declarations, objects);
  if (const std::optional<int> waves =
          sharedWaveSources(scene, geometry.usedMaterials(), *camera, issues)) {
    // Known once the materials in use are: a second block, as POV-Ray takes each setting
    // wherever it is written.
    out.open("global_settings");
    out.line(fmt::format("number_of_waves {}", *waves));
    out.close();
    out.blank();
  }

  const bool anySpecular = materials.anySpecular(geometry.usedMaterials());
  // A light group's lights are written inside its light_group (povray/pov_geometry.cpp).
  // A light projected through objects comes after the mesh declarations its objects may
  // make (PovGeometry::writeProjection).
  PovWriter projected;
  for (const Light& light : scene.lights) {
    if (light.group != 0) continue;
    if (!light.projectedThrough) {
      writeLight(light, anySpecular, out, issues);
      continue;
    }
    writeLight(light, anySpecular, projected, issues,
               [&](PovWriter& w) { geometry.writeProjection(light, w); });
  }
  geometry.takeMeshDeclarations(declarations);
  if (!scene.lights.empty()) out.blank();
  // The object patterns' objects before the materials that name them, and the meshes
  // they may hold before them (a mesh declaration holds no texture).
  if (!objectPatterns.text().empty()) {
    out.append(declarations);
    declarations = PovWriter();
    out.append(objectPatterns);
    out.blank();
  }
  materials.writeDeclarations(geometry.usedMaterials(), out);
  out.blank();
  out.append(declarations);
  if (!projected.text().empty()) {
    out.append(projected);
    out.blank();
  }
  out.append(objects);

  result.issues = issues.all();
  if (result.ok()) result.text = out.text();
  return result;
}

}  // namespace lucent
