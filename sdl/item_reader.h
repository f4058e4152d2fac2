// The seam between the language core and the scene reader (docs/povray-import.md): a value
// of the language may be an item the scene reader made (an object, a texture, a camera...),
// and the core asks the reader for one where a right-hand side is not an expression.
#pragma once

#include <memory>
#include <string_view>

namespace lucent::sdl {

class TokenStream;
struct Token;

struct Item {
  virtual ~Item() = default;
  // The keyword that made it: "sphere", "texture", "camera"...
  virtual std::string_view kind() const = 0;
};
using ItemPtr = std::shared_ptr<const Item>;

class ItemReader {
 public:
  virtual ~ItemReader() = default;
  // The item that starts with keyword `t` (already read: "sphere", "texture", ...), read to
  // its closing brace from `in`; nullptr if `t` starts no item (then it is an expression).
  // `t` may be the stream's current token, which changes as `in` is read: take what is
  // needed of it first.
  virtual ItemPtr read(const Token& t, TokenStream& in) = 0;
};

}  // namespace lucent::sdl
