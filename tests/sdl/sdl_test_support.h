// Running POV-Ray SDL text through the language core in tests: the #debug output, the
// first error, and an item reader that skips items (so that includes declaring
// functions, such as math.inc, can be read).
#pragma once

#include "sdl/options.h"
#include "sdl/token_stream.h"

#include <filesystem>
#include <memory>
#include <string>

namespace sdltest {

struct SkippedItem : lucent::sdl::Item {
  std::string word;
  std::string_view kind() const override { return word; }
};

// Reads an item as `keyword [( ... )] { ... }`, keeping only its keyword.
class SkippingItemReader : public lucent::sdl::ItemReader {
 public:
  lucent::sdl::ItemPtr read(const lucent::sdl::Token& t, lucent::sdl::TokenStream& in) override {
    auto item = std::make_shared<SkippedItem>();
    item->word = std::string(t.text());
    if (in.peek().is("(")) skip(in, "(", ")");
    skip(in, "{", "}");
    return item;
  }

 private:
  static void skip(lucent::sdl::TokenStream& in, const char* open, const char* close) {
    in.expect(open);
    for (int depth = 1; depth > 0;) {
      const lucent::sdl::Token& t = in.next();
      if (t.kind == lucent::sdl::TokenKind::End) in.error(t, "unclosed item");
      if (t.is(open)) ++depth;
      if (t.is(close)) --depth;
    }
  }
};

// The folder of the scripts of tests/data/sdl.
std::filesystem::path dataFolder();

// Evaluates `text` as the file `name` in tests/data/sdl, items skipped; returns the
// #debug output. Throws SdlError.
std::string debugOf(const std::string& text, lucent::sdl::CollectedOutput* out = nullptr,
                    lucent::sdl::Options options = {});

// The same, returning the error's whole text (what()), or "" when there is none.
std::string errorOf(const std::string& text, lucent::sdl::Options options = {});

}  // namespace sdltest
