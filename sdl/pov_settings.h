// POV-Ray's scene-wide blocks: global_settings, background, sky_sphere and fog, and the
// Lucent scene settings they make (docs/povray-import.md, "Scene settings").
#pragma once

#include "pov_finish.h"
#include "pov_space.h"

#include "scenegraph/fog.h"
#include "scenegraph/render_settings.h"
#include "scenegraph/sky.h"
#include "scenegraph/source_loc.h"

#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

// `global_settings { ... }` with POV-Ray 3.7's defaults.
struct PovGlobalSettings {
  std::optional<double> assumedGamma;  // none written: 1.0 under #version 3.7
  bool assumedGammaSrgb = false;       // assumed_gamma srgb (assumedGamma then holds 1)
  int maxTraceLevel = 5;
  double adcBailout = 1.0 / 255.0;
  Color ambientLight{1.0f};
  // The noise of the patterns that do not choose theirs (POV-Ray 3.7's default, range
  // corrected); the importer marks those patterns with 0 until the scene is read.
  int noiseGenerator = 2;
  int numberOfWaves = kDefaultWaveSources;  // the sources of ripples and waves
};

// `background { colour }` (default black; its filter and transmit do not show).
struct PovBackground {
  Color color{0.0f};
};

// `sky_sphere { pigment {...} ... transforms }`: each pigment a layer of Lucent's <sky>,
// the last on top, as POV-Ray layers them.
struct PovSkySphere {
  std::vector<PovPigment> pigments;
  PovTransform transform;  // the sky_sphere's own transforms
  SourceLoc loc;
};

// `fog { ... }`: fog_type 1 (constant) or 2 (ground), with POV-Ray's defaults. A scene
// layers every fog it has.
struct PovFog {
  int type = 1;
  SourceLoc loc;
  double distance = 0.0;  // POV-Ray needs one above 0
  Color color{0.0f};
  float filter = 0.0f;
  float transmit = 0.0f;
  double offset = 0.0;    // fog_offset
  double altitude = 0.0;  // fog_alt
  Vec3 up{0.0, 1.0, 0.0};
  // POV-Ray's fog turbulence: it exists once any of turbulence, octaves, omega or lambda
  // is written (the vector then defaults to 0), with these defaults.
  bool turbulent = false;
  Vec3 turbulence{0.0};
  int octaves = 6;  // clamped to 1..10 as POV-Ray's parser does
  double omega = 0.5;
  double lambda = 2.0;
  double turbDepth = 0.5;  // turb_depth: used only when turbulent
  PovTransform transform;
};

// global_settings and background into the render settings (size and sampling are the
// command line's), with the working gamma POV-Ray takes for the scene's language version
// (the last #version: below 3.7 without an assumed_gamma, POV-Ray turns gamma off and
// writes its values as they are). Returns what differs from POV-Ray's meaning.
std::vector<std::string> applyGlobalSettings(const PovGlobalSettings& g,
                                             const PovBackground& background,
                                             RenderSettings& render, double languageVersion = 3.7);

// The working gamma POV-Ray computes with under `languageVersion` (applyGlobalSettings').
WorkingGamma povWorkingGamma(const PovGlobalSettings& g, double languageVersion);

struct SkyImport {
  std::optional<Sky> sky;
  std::vector<std::string> differences;
  std::string error;  // set when the sky cannot be imported at all
};
SkyImport importSkySphere(const PovSkySphere& sky);

struct FogImport {
  std::optional<Fog> fog;
  std::vector<std::string> differences;
  std::string error;
};
FogImport importFog(const PovFog& fog);

}  // namespace lucent::sdl
