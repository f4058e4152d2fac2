// #declare and #local, the right-hand side of a declaration or a macro argument, and
// arrays. POV-Ray's scoping: #declare assigns the innermost visible identifier of that
// name, or makes a global one; #local assigns one of the current table (the include file's
// or the macro call's), or makes one there.
#include "token_stream.h"

#include <utility>

namespace lucent::sdl {

void TokenStream::declare(bool local, const SourceLoc& at) {
  okToDeclare_ = false;
  lvalueOk_ = true;
  getToken();
  if (cur_.kind == TokenKind::Keyword && cur_.kw == Kw::k_deprecated) {
    getToken();  // `deprecated [once] ["message"]`: read, and no warning given
    if (cur_.kind == TokenKind::Keyword && cur_.kw == Kw::k_once) getToken();
    if (cur_.kind == TokenKind::String) getToken();
  }
  lvalueOk_ = false;
  const Token target = cur_;
  const std::string name(target.text());
  const int top = static_cast<int>(tables_.size()) - 1;
  bool fresh = false;
  switch (target.kind) {
    case TokenKind::Undeclared:
      fresh = true;
      break;
    case TokenKind::Identifier:
      fresh = local && !target.element && target.table != top;
      break;
    case TokenKind::MacroName:
      error(target, "'" + name + "' is a macro; #undef it before declaring a value by that name");
    case TokenKind::Keyword:
      error(target, "'" + name + "' is a reserved word; it cannot be declared");
    default:
      error(target, "expected an identifier to declare, found " + target.describe());
  }
  expect("=");
  okToDeclare_ = true;
  Value v;
  declaring_ = name;
  if (!rvalue(v, nullptr, false, true)) {
    getToken();
    error(cur_,
          "expected a value to declare (an expression, a string, an array or an item), "
          "found " +
              cur_.describe());
  }
  if (fresh) {
    auto s = std::make_shared<Symbol>();
    s->value = std::move(v);
    tables_[local ? top : 0][name] = s;
  } else {
    store(target.ref, std::move(v), at);
  }
  okToDeclare_ = false;
  allow(";");
  okToDeclare_ = true;
}

void TokenStream::store(const Ref& target, Value v, const SourceLoc& at) {
  if (target.array) assignElement(*target.array, target.index, std::move(v), at);
  else target.set(std::move(v));
}

// POV-Ray 3.7's arrays hold one type: the first element given sets it.
void TokenStream::assignElement(ArrayValue& a, size_t index, Value v, const SourceLoc& at) {
  if (a.elementType && *a.elementType != v.type) {
    Value was;
    was.type = *a.elementType;
    error(at, "attempted to redefine " + typeName(was) + " as " + typeName(v) +
                  " (the elements of a POV-Ray 3.7 array have one type)");
  }
  a.elementType = v.type;
  a.elements[index] = std::move(v);
}

// A right-hand side: an expression, a colour, a string, an array, an identifier's value,
// or an item (asked of the scene reader). For a macro argument (`parameter`), a lone
// identifier is passed by reference: `byRef` then says where its value lives.
bool TokenStream::rvalue(Value& out, Ref* byRef, bool parameter, bool semicolonAfter) {
  Nesting nesting(*this);
  const bool prevOk = okToDeclare_;
  // The name being declared belongs to this right-hand side only (not to an array's elements).
  const std::string declaring = std::exchange(declaring_, std::string());
  getToken();
  const Token t = cur_;
  bool found = true;
  const Value* tv = t.kind == TokenKind::Identifier ? t.value() : nullptr;
  if (tv && !tv->isNumeric() &&
      !((tv->type == ValueType::Function || tv->type == ValueType::Spline) && t.call)) {
    if (parameter && byRef) *byRef = t.ref;
    else out = copyValue(*tv);
  } else if (t.kind == TokenKind::Keyword && t.text() == "function") {
    out = Value{};
    out.type = ValueType::Function;
    out.function = parseFunction(true, parameter ? std::string() : declaring);
  } else if (t.kind == TokenKind::Keyword && t.text() == "spline") {
    out = Value{};
    out.type = ValueType::Spline;
    out.spline = splineBlock();
  } else if (t.kind == TokenKind::Undeclared) {
    error(t, parameter ? "cannot pass undeclared identifier '" + std::string(t.text()) +
                             "' as a macro parameter"
                       : "undeclared identifier '" + std::string(t.text()) + "'");
  } else if (t.kind == TokenKind::String ||
             (t.kind == TokenKind::Keyword && isStringFunction(t.kw))) {
    unget_ = true;
    std::string s;
    stringExpression(s, false, true);
    out = Value::string(std::move(s));
  } else if (t.kind == TokenKind::Keyword && t.kw == Kw::k_array) {
    out = Value{};
    out.type = ValueType::Array;
    out.array = arrayDeclaration();
  } else if (rvalueNumeric(out, byRef, parameter, semicolonAfter)) {
    // done
  } else if (t.kind == TokenKind::Keyword && items_) {
    ItemPtr item = items_->read(t, *this);
    if (item) {
      out = Value{};
      out.type = ValueType::Item;
      out.item = std::move(item);
    } else {
      unget_ = true;
      found = false;
    }
  } else {
    unget_ = true;
    found = false;
  }
  okToDeclare_ = prevOk;
  return found;
}

// The numeric right-hand sides: a colour (`rgb ...`, `color ...`), or an expression whose
// size makes the type (1 a float, 2 uv, 3 vector, 4, 5 a colour). cur_ is its first token.
bool TokenStream::rvalueNumeric(Value& out, Ref* byRef, bool parameter, bool semicolonAfter) {
  const Token t = cur_;
  const Value* tv = t.kind == TokenKind::Identifier ? t.value() : nullptr;
  const bool colourWord = t.kind == TokenKind::Keyword &&
                          (t.kw == Kw::k_color || t.kw == Kw::k_colour || isColourKey(t.kw));
  if (colourWord || (tv && tv->type == ValueType::Colour && version_ < 350)) {
    unget_ = true;
    okToDeclare_ = false;
    std::array<double, 5> c = colour(true);
    if (semicolonAfter) semicolon(true);
    okToDeclare_ = true;
    out = Value::numeric(c.data(), 5);
    return true;
  }
  if (!startsExpression(t)) return false;
  const bool single = parameter && byRef && tv;
  unget_ = true;
  okToDeclare_ = false;
  const std::uint64_t before = tokens_;
  Express e;
  int terms = unknownVector(e);
  const bool oneToken = tokens_ - before == 1;
  if (semicolonAfter) semicolon(true);
  if (single && oneToken) *byRef = t.ref;
  else out = Value::numeric(e.v, terms);
  okToDeclare_ = true;
  return true;
}

void TokenStream::semicolon(bool force) {
  getToken();
  if (cur_.is(";")) return;
  unget_ = true;
  if (version_ >= 350 && force)
    error(cur_,
          "expected ';' after the value: every #declare or #local of a float, vector "
          "or colour ends with ';' since POV-Ray 3.5 (found " +
              cur_.describe() + ")");
  if (version_ >= 310)
    warning(cur_.loc(),
            "all #version and #declares of float, vector, and color require "
            "semi-colon ';' at end");
}

// `array[n]...[m] { initialisers }`, the keyword read.
std::shared_ptr<ArrayValue> TokenStream::arrayDeclaration() {
  auto a = std::make_shared<ArrayValue>();
  okToDeclare_ = false;
  size_t total = 1;
  while (allow("[")) {
    if (a->sizes.size() == 5) error(cur_, "too many array dimensions (POV-Ray takes 5)");
    const Token at = cur_;
    double size = parseFloat();
    if (!(size > -1e15 && size < 1e15)) size = 0;  // NaN or absurd: refused below
    long long n = static_cast<long long>(size + 1e-10);
    if (n <= 0) error(at, "invalid dimension size for an array: " + std::to_string(n));
    total *= static_cast<size_t>(n);
    if (total > options_.limits.arrayElements)
      error(at, "an array of more than " + std::to_string(options_.limits.arrayElements) +
                    " elements (the limit of one array; see docs/povray-import.md)");
    a->sizes.push_back(static_cast<int>(n));
    expect("]");
  }
  if (a->sizes.empty()) error(cur_, "an array declaration must have at least one dimension");
  a->strides.assign(a->sizes.size(), 1);
  for (size_t d = a->sizes.size() - 1; d > 0; --d)
    a->strides[d - 1] = a->strides[d] * static_cast<size_t>(a->sizes[d]);
  a->elements.resize(total);
  getToken();
  unget_ = true;
  if (cur_.is("{")) arrayInitialiser(*a, 0, 0);
  okToDeclare_ = true;
  return a;
}

void TokenStream::arrayInitialiser(ArrayValue& a, size_t dim, size_t base) {
  expect("{");
  for (int i = 0; i < a.sizes[dim]; ++i) {
    const size_t at = base + static_cast<size_t>(i) * a.strides[dim];
    if (dim + 1 < a.sizes.size()) {
      arrayInitialiser(a, dim + 1, at);
      continue;
    }
    Value v;
    const SourceLoc elementLoc = peek().loc();
    if (!rvalue(v, nullptr, false, false)) {
      getToken();
      error(cur_, "insufficient number of initializers: expected " + std::to_string(a.sizes[dim]) +
                      ", found " + cur_.describe());
    }
    assignElement(a, at, std::move(v), elementLoc);
    parseComma();
  }
  expect("}");
  parseComma();
}

}  // namespace lucent::sdl
