#include "sdl_test_support.h"

#include "../support/paths.h"

namespace sdltest {

using namespace lucent::sdl;

std::filesystem::path dataFolder() {
  return std::filesystem::path(lucentSourceDir()) / "tests" / "data" / "sdl";
}

std::string debugOf(const std::string& text, CollectedOutput* out, Options options) {
  CollectedOutput local;
  if (!out) out = &local;
  options.output = out;
  SkippingItemReader items;
  TokenStream in(options, &items);
  in.openText("test.pov", text, dataFolder());
  for (;;) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) break;
    if (t.kind != TokenKind::Keyword) in.error(t, "unexpected " + t.describe());
    items.read(t, in);
  }
  return out->debugText;
}

std::string errorOf(const std::string& text, Options options) {
  try {
    debugOf(text, nullptr, std::move(options));
  } catch (const SdlError& e) {
    return e.what();
  }
  return "";
}

}  // namespace sdltest
