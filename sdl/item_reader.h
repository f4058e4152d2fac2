// The seam between the language core and the scene reader (docs/povray-import.md): a value
// of the language may be an item the scene reader made (an object, a texture, a camera...),
// and the core asks the reader for one where a right-hand side is not an expression.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string_view>

namespace lucent::sdl {

class TokenStream;
struct Token;
struct FunctionValue;

struct Item {
  virtual ~Item() = default;
  // The keyword that made it: "sphere", "texture", "camera"...
  virtual std::string_view kind() const = 0;
};
using ItemPtr = std::shared_ptr<const Item>;

// An object's geometry as the scene reader builds it (Lucent's own shapes), for trace(),
// inside(), min_extent() and max_extent(); every point and direction in POV-Ray's space.
class ObjectGeometry {
 public:
  using Vec = std::array<double, 3>;
  virtual ~ObjectGeometry() = default;
  // The first surface the ray from `origin` along `direction` meets: its point and its
  // unit normal; false when it meets none.
  virtual bool trace(const Vec& origin, const Vec& direction, Vec& point, Vec& normal) const = 0;
  virtual bool inside(const Vec& point) const = 0;
  // The corners of the box that bounds the object.
  virtual void extent(Vec& lo, Vec& hi) const = 0;
};

class ItemReader {
 public:
  virtual ~ItemReader() = default;
  // The geometry of an object item; null when `item` is not an object this reader can
  // build. Throws SdlError (at `at`) for an object it cannot build.
  virtual std::shared_ptr<const ObjectGeometry> geometry(const std::shared_ptr<const Item>& item,
                                                         TokenStream& in) {
    (void)item;
    (void)in;
    return nullptr;
  }
  // The item that starts with keyword `t` (already read: "sphere", "texture", ...), read to
  // its closing brace from `in`; nullptr if `t` starts no item (then it is an expression).
  // `t` may be the stream's current token, which changes as `in` is read: take what is
  // needed of it first.
  virtual ItemPtr read(const Token& t, TokenStream& in) = 0;
  // A pattern function's pattern as a pigment item whose red component is the pattern's
  // value: `pattern { PATTERN modifiers }` read from `in` (the keyword `pattern` read), or,
  // when `noise`, POV-Ray's noise (f_noise3d) read from nothing. Null when this reader
  // makes no pigments (then such functions are refused where called).
  // The component `member` (0 red ... 5 gray) of the pigment function `f`'s colour at the
  // point xyz (POV-Ray's space), evaluated now; empty when this reader cannot.
  virtual std::optional<double> pigmentValue(const FunctionValue& f, int member,
                                             const double* xyz) {
    (void)f;
    (void)member;
    (void)xyz;
    return std::nullopt;
  }
  virtual ItemPtr patternPigment(TokenStream& in, bool noise) {
    (void)in;
    (void)noise;
    return nullptr;
  }
};

}  // namespace lucent::sdl
