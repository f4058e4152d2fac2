// <render> (contract, "<render>"): image size, samples and adaptive sampling (with its
// corners mode, docs/scene-language.md), recursion limits, background,
// global ambient, an optional self-intersection epsilon ("auto" or absent: automatic) and
// the working gamma (POV-Ray's assumed_gamma).
#include "element_parsers.h"
#include "gamma_attribute.h"

#include "scenegraph/render_limits.h"

namespace lucent {

void parseRender(ElementReader& r) {
  ParseContext& ctx = r.ctx();
  if (ctx.hasRender) {
    r.error("<render> is given twice (first at " + ctx.renderLoc.str() + ")");
    return;
  }
  ctx.hasRender = true;
  ctx.renderLoc = r.loc();

  r.checkAttributes({"width", "height", "samples", "adaptive", "adaptive-mode", "adaptive-depth",
                     "max-depth", "min-weight", "background", "ambient", "epsilon",
                     "working-gamma"});
  RenderSettings& s = ctx.scene.render;
  s.loc = r.loc();
  // The limits are explained in render_settings.h.
  s.width = static_cast<int>(r.integer("width", s.width, 1, kMaxImageSide));
  s.height = static_cast<int>(r.integer("height", s.height, 1, kMaxImageSide));
  s.samples = static_cast<int>(r.integer("samples", s.samples, 1, kMaxSamples));
  s.adaptive = r.number("adaptive", s.adaptive, NumberRule::nonNegative());
  s.adaptiveMode =
      r.choice("adaptive-mode", s.adaptiveMode,
               {{"centers", AdaptiveMode::Centres}, {"corners", AdaptiveMode::Corners}});
  if (s.adaptiveMode == AdaptiveMode::Corners) {
    s.adaptiveDepth =
        static_cast<int>(r.integer("adaptive-depth", s.adaptiveDepth, 1, kMaxAdaptiveDepth));
    // Corner sampling chooses its own samples; a `samples` it would ignore is a mistake.
    if (s.samples > 1)
      r.attrError("samples",
                  "adaptive-mode=\"corners\" chooses its own samples (up to "
                  "(2^(adaptive-depth - 1) + 1)^2 a pixel); remove 'samples' or use "
                  "adaptive-mode=\"centers\"");
  } else if (r.has("adaptive-depth")) {
    r.attrError("adaptive-depth", "applies only with adaptive-mode=\"corners\"");
  }
  s.maxDepth = static_cast<int>(r.integer("max-depth", s.maxDepth, 1, kMaxRecursionDepth));
  s.minWeight =
      r.number("min-weight", s.minWeight, NumberRule::between(0.0, 1.0, "a number from 0 to 1"));
  s.background = r.color("background", s.background);
  s.ambient = r.color("ambient", s.ambient);
  if (auto e = r.text("epsilon"); e && trim(*e) != "auto")
    s.epsilon = r.optionalNumber("epsilon", NumberRule::positive());
  // POV-Ray's assumed_gamma: a power above 0, or srgb.
  if (auto g = readGammaAttribute(r, "working-gamma")) s.workingGamma = *g;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader(ctx, r.file(), n)
        .error("<render> takes no child elements, got <" + std::string(n.name()) + ">");
  });
}

}  // namespace lucent
