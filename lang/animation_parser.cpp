// <animation frames clock-from clock-to cyclic> (contract, "Animation"): read before anything
// else, because every other element may use clock, frame and frames.
#include "element_parsers.h"

#include <cmath>

namespace lucent {

namespace {

constexpr long long kMaxFrames = 1'000'000;

void parseAnimation(ElementReader& r) {
  r.checkAttributes({"frames", "clock-from", "clock-to", "cyclic"});
  r.forEachChild([&](pugi::xml_node c) {
    ElementReader(r.ctx(), r.file(), c)
        .error("<animation> takes no child elements, got <" + std::string(c.name()) + ">");
  });
  Animation& a = r.ctx().scene.animation;
  a.present = true;
  if (!r.has("frames")) r.error("<animation> needs 'frames' (how many frames the sequence has)");
  a.frames = static_cast<int>(r.integer("frames", 1, 1, kMaxFrames));
  a.clockFrom = r.number("clock-from", 0.0);
  a.clockTo = r.number("clock-to", 1.0);
  a.cyclic = r.boolean("cyclic", false);
}

}  // namespace

void readAnimation(ParseContext& ctx, const std::vector<TopLevelItem>& items, int frame) {
  const TopLevelItem* first = nullptr;
  for (const TopLevelItem& item : items) {
    if (std::string_view(item.element.name()) != "animation") continue;
    ElementReader r(ctx, *item.file, item.element);
    if (first) {
      r.error("a scene has one <animation> at most; the first is at " +
              first->file->loc(first->element).str());
      continue;
    }
    first = &item;
    parseAnimation(r);
  }
  Animation& a = ctx.scene.animation;
  SourceLoc commandLine{ctx.scene.file, 0, 0};
  if (const std::string* d = ctx.params.define("frame")) {
    Parsed<long long> f = parseInteger(*d);
    if (!f) ctx.diags.error(commandLine, "-D frame=" + *d + ": expected a whole number");
    else frame = static_cast<int>(std::max(-1LL, std::min<long long>(*f, kMaxFrames + 1)));
  }
  if (frame < 1 || frame > a.frames) {
    ctx.diags.error(commandLine, "frame " + std::to_string(frame) +
                                     " does not exist: the scene has " + std::to_string(a.frames) +
                                     (a.frames == 1 ? " frame" : " frames"));
    frame = 1;
  }
  double clock = a.clockOf(frame);
  if (const std::string* d = ctx.params.define("clock")) {
    Parsed<double> c = parseNumber(*d);
    if (!c) ctx.diags.error(commandLine, "-D clock=" + *d + ": " + c.error);
    else clock = *c;
  }
  ctx.scene.frame = frame;
  ctx.scene.clock = clock;
  ctx.params.setBuiltin("frame", frame);
  ctx.params.setBuiltin("frames", a.frames);
  ctx.params.setBuiltin("clock", clock);
}

}  // namespace lucent
