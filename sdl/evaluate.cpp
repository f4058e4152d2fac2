#include "evaluate.h"

namespace lucent::sdl {

namespace {

void refuse(const Token& t, const TokenStream& in) {
  if (t.kind == TokenKind::Keyword)
    in.error(t, "'" + std::string(t.kw == Kw::k_default ? "#" : "") + std::string(t.text()) +
                    "' is not read yet (Lucent's POV-Ray reader "
                    "evaluates the language, not yet the scene items)");
  in.error(t, "unexpected " + t.describe() + " at the top level of the scene");
}

void run(TokenStream& in) {
  for (;;) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) return;
    refuse(t, in);
  }
}

}  // namespace

ItemPtr RefusingItemReader::read(const Token& t, TokenStream& in) {
  refuse(t, in);
  return nullptr;
}

void evaluateFile(const std::filesystem::path& path, const Options& options) {
  RefusingItemReader items;
  TokenStream in(options, &items);
  in.openFile(path);
  run(in);
}

void evaluateText(const std::string& name, const std::string& text,
                  const std::filesystem::path& folder, const Options& options) {
  RefusingItemReader items;
  TokenStream in(options, &items);
  in.openText(name, text, folder);
  run(in);
}

}  // namespace lucent::sdl
