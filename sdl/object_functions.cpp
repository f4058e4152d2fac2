// trace(), inside(), min_extent() and max_extent(): the functions that ask about an object,
// evaluated with Lucent's own geometry of it, which the scene reader builds
// (ItemReader::geometry). As in POV-Ray, the object is an identifier.
#include "token_stream.h"

namespace lucent::sdl {

std::shared_ptr<const ObjectGeometry> TokenStream::objectArgument(const Token& function) {
  const std::string name(function.text());
  getToken();
  const Value* v = cur_.kind == TokenKind::Identifier ? cur_.value() : nullptr;
  std::shared_ptr<const ObjectGeometry> geometry;
  if (v && v->type == ValueType::Item && items_) geometry = items_->geometry(v->item, *this);
  if (!geometry) error(cur_, name + "() needs an object identifier first, not " + cur_.describe());
  return geometry;
}

// trace(OBJECT, A, B [, NORMAL]): where the ray from A along B first meets the object, and
// its normal into the identifier NORMAL; <0, 0, 0> for both when it meets nothing.
std::array<double, 3> TokenStream::traceFunction() {
  const Token at = cur_;
  expect("(");
  const auto geometry = objectArgument(at);
  parseComma();
  const std::array<double, 3> origin = parseVector();
  parseComma();
  const std::array<double, 3> direction = parseVector();
  std::array<double, 3> point{0, 0, 0}, normal{0, 0, 0};
  const bool dirLength = direction[0] != 0 || direction[1] != 0 || direction[2] != 0;
  if (dirLength && !geometry->trace(origin, direction, point, normal)) point = normal = {0, 0, 0};
  if (allow(",")) {
    lvalueOk_ = true;
    getToken();
    lvalueOk_ = false;
    const Token target = cur_;
    declareAs(target, Value::numeric(normal.data(), 3), target.loc());
  }
  expect(")");
  return point;
}

double TokenStream::insideFunction() {
  const Token at = cur_;
  expect("(");
  const auto geometry = objectArgument(at);
  parseComma();
  const std::array<double, 3> p = parseVector();
  expect(")");
  return geometry->inside(p) ? 1.0 : 0.0;
}

std::array<double, 3> TokenStream::extentFunction(Kw kw) {
  const Token at = cur_;
  expect("(");
  const auto geometry = objectArgument(at);
  expect(")");
  std::array<double, 3> lo{}, hi{};
  geometry->extent(lo, hi);
  return kw == Kw::k_min_extent ? lo : hi;
}

}  // namespace lucent::sdl
