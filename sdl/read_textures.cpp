// Textures: pigment (a colour, for now), finish, texture and interior blocks, each starting
// from what POV-Ray starts it from (the #default, or an identifier written first).
#include "read_support.h"
#include "scene_reader.h"

namespace lucent::sdl {

namespace {

bool isColourStart(const Token& t) {
  if (t.kind == TokenKind::Keyword)
    return t.kw == Kw::k_color || t.kw == Kw::k_colour || isColourKey(t.kw);
  return startsNumber(t);
}

}  // namespace

PovPigment SceneReader::readPigment(TokenStream& in, const PovPigment& start) {
  PovPigment p = start;
  in.expect("{");
  if (const auto* item = dynamic_cast<const PigmentItem*>(itemOf(in.peek()))) {
    in.next();
    p = item->pigment;
  }
  PovTransform ignored;  // a colour looks the same however it is moved
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return p;
    if (isColourStart(t)) {
      in.unget();
      const PovColour c = readColour(in);
      p.color = c.rgb;
      p.filter = c.filter;
      p.transmit = c.transmit;
    } else if (!readTransform(t, in, ignored)) {
      unreadInBlock(t, in);
      return p;
    }
  }
}

PovFinish SceneReader::readFinish(TokenStream& in, const PovFinish& start) {
  PovFinish f = start;
  in.expect("{");
  if (const auto* item = dynamic_cast<const FinishItem*>(itemOf(in.peek()))) {
    in.next();
    f = item->finish;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return f;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (isWord(in.peek(), "albedo")) {
      const Token albedo = in.next();
      unreadInBlock(albedo, in);
      return f;
    }
    if (w == "ambient") {
      f.ambient = readColour(in).rgb;
    } else if (w == "emission") {
      f.emission = readColour(in).rgb;
    } else if (w == "diffuse") {
      f.diffuse = in.parseFloat();
      if (in.allow(",")) {
        in.parseFloat();
        warn(in, t.loc(), "the diffuse of the back side is not imported (Lucent lights the front)");
      }
    } else if (w == "brilliance") {
      f.brilliance = in.parseFloat();
    } else if (w == "phong") {
      f.phong = in.parseFloat();
    } else if (w == "phong_size") {
      f.phongSize = in.parseFloat();
    } else if (w == "specular") {
      f.specular = in.parseFloat();
    } else if (w == "roughness") {
      f.roughness = in.parseFloat();
    } else if (w == "metallic") {
      f.metallic = startsNumber(in.peek()) ? in.parseFloat() : 1.0;
    } else if (w == "reflection") {
      if (in.peek().is("{")) {
        in.next();
        readReflection(in, f.reflection);
      } else {
        f.reflection.min = f.reflection.max = readColour(in).rgb;
      }
    } else if (w == "reflection_exponent") {
      f.reflection.exponent = in.parseFloat();
    } else if (w == "conserve_energy") {
      f.conserveEnergy = optionalBool(in);
    } else if (w == "irid") {
      in.expect("{");
      f.irid = in.parseFloat();
      for (;;) {
        const Token k = in.next();
        if (k.is("}")) break;
        if (isWord(k, "thickness")) f.iridThickness = in.parseFloat();
        else if (isWord(k, "turbulence")) f.iridTurbulence = in.parseFloat();
        else in.error(k, "unexpected " + k.describe() + " in irid");
      }
    } else if (w == "crand") {
      in.parseFloat();
      warn(in, t.loc(), "crand is not imported (Lucent's surfaces have no graininess)");
    } else {
      unreadInBlock(t, in);
      return f;
    }
  }
}

// `reflection { [MIN,] MAX fresnel falloff F exponent F metallic [F] }` (the '{' read).
void SceneReader::readReflection(TokenStream& in, PovReflection& r) {
  const Color first = readColour(in).rgb;
  r.min = r.max = first;
  if (in.allow(",")) r.max = readColour(in).rgb;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return;
    if (isWord(t, "fresnel")) r.fresnel = optionalBool(in);
    else if (isWord(t, "falloff")) r.falloff = in.parseFloat();
    else if (isWord(t, "exponent")) r.exponent = in.parseFloat();
    else if (isWord(t, "metallic")) r.metallic = startsNumber(in.peek()) ? in.parseFloat() : 1.0;
    else in.error(t, "unexpected " + t.describe() + " in reflection");
  }
}

PovTexture SceneReader::readTexture(TokenStream& in, const PovTexture& start) {
  PovTexture tex = start;
  in.expect("{");
  if (const auto* item = dynamic_cast<const TextureItem*>(itemOf(in.peek()))) {
    in.next();
    tex = item->texture;
  }
  PovTransform ignored;  // a solid colour looks the same however it is moved
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return tex;
    if (isWord(t, "pigment")) tex.pigment = readPigment(in, defaults_.pigment);
    else if (isWord(t, "finish")) tex.finish = readFinish(in, defaults_.finish);
    else if (!readTransform(t, in, ignored)) {
      unreadInBlock(t, in);
      return tex;
    }
  }
}

PovInterior SceneReader::readInterior(TokenStream& in, const PovInterior& start) {
  PovInterior i = start;
  in.expect("{");
  if (const auto* item = dynamic_cast<const InteriorItem*>(itemOf(in.peek()))) {
    in.next();
    i = item->interior;
  }
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return i;
    if (isWord(t, "ior")) i.ior = in.parseFloat();
    else if (isWord(t, "fade_distance")) i.fadeDistance = in.parseFloat();
    else if (isWord(t, "fade_power")) i.fadePower = in.parseFloat();
    else if (isWord(t, "fade_color") || isWord(t, "fade_colour")) i.fadeColor = readColour(in).rgb;
    else if (t.kind == TokenKind::Keyword) {
      unsupported(t, in, true);
      if (startsNumber(in.peek())) in.parseFloat();  // caustics F, dispersion F
    } else in.error(t, "unexpected " + t.describe() + " in interior");
  }
}

// `material { [Identifier] texture { } interior { } }`; its transforms move a texture that
// is a solid colour for now, so they change nothing.
PovMaterial SceneReader::readMaterial(TokenStream& in) {
  PovMaterial m;
  in.expect("{");
  if (const auto* item = dynamic_cast<const MaterialItem*>(itemOf(in.peek()))) {
    in.next();
    m = item->material;
  }
  PovTransform ignored;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) return m;
    if (isWord(t, "texture")) m.texture = readTexture(in, defaultTexture());
    else if (isWord(t, "interior"))
      m.interior = readInterior(in, m.interior ? *m.interior : PovInterior{});
    else if (!readTransform(t, in, ignored)) {
      unreadInBlock(t, in);
      return m;
    }
  }
}

}  // namespace lucent::sdl
