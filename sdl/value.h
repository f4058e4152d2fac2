// The values of POV-Ray's language: a float, a vector of 2, 3 or 4 components, a colour
// (5 components: red, green, blue, filter, transmit), a string, an array, an item made
// by the scene reader (item_reader.h), a function (function.h) or a spline (spline.h). POV-Ray
// gives a value the type of the expression that made it: `<1,2>` is a 2-vector, `rgb 1` and
// `<1,2,3,4,5>` are colours.
#pragma once

#include "item_reader.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucent::sdl {

enum class ValueType { Float, Uv, Vector, Vector4, Colour, String, Array, Item, Function, Spline };

struct ArrayValue;
struct FunctionValue;  // function.h
struct Spline;         // spline.h

struct Value {
  ValueType type = ValueType::Float;
  std::array<double, 5> v{};  // the float in v[0], or the components
  std::shared_ptr<const std::string> str;
  std::shared_ptr<ArrayValue> array;
  ItemPtr item;
  std::shared_ptr<const FunctionValue> function;  // Function: a `function { }`
  std::shared_ptr<const Spline> spline;           // Spline: a `spline { }`

  static Value number(double f);
  // A value of `terms` components (1 a float, 2 uv, 3 vector, 4, 5 a colour, whose
  // components are rounded to single precision as POV-Ray stores them).
  static Value numeric(const double* e, int terms);
  static Value string(std::string s);

  bool isNumeric() const { return type <= ValueType::Colour; }
  // 1 for a float, the components of a vector or colour, 0 otherwise.
  int terms() const;
};

// "float identifier", "vector identifier", "sphere identifier"...: how POV-Ray names the
// type in its messages.
std::string typeName(const Value& v);

// An array of 1 to 5 dimensions of fixed sizes, whose elements all have one type: the type
// of the first element given (POV-Ray 3.7).
struct ArrayValue {
  std::vector<int> sizes;
  std::vector<size_t> strides;
  std::vector<std::optional<Value>> elements;
  std::optional<ValueType> elementType;
  std::string elementKind;  // for items: the kind of the first

  // A deep copy: POV-Ray copies an array assigned to another identifier.
  std::shared_ptr<ArrayValue> clone() const;
};

// A value copied as POV-Ray copies an identifier's value (arrays deeply).
Value copyValue(const Value& v);

}  // namespace lucent::sdl
