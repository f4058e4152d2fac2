#include "value.h"

namespace lucent::sdl {

Value Value::number(double f) {
  Value r;
  r.v[0] = f;
  return r;
}

Value Value::numeric(const double* e, int terms) {
  static constexpr ValueType kTypes[] = {ValueType::Float,  ValueType::Float,   ValueType::Uv,
                                         ValueType::Vector, ValueType::Vector4, ValueType::Colour};
  Value r;
  r.type = kTypes[terms];
  for (int i = 0; i < terms; ++i) r.v[i] = e[i];
  // POV-Ray keeps colour components in single precision.
  if (terms == 5)
    for (double& c : r.v) c = static_cast<float>(c);
  return r;
}

Value Value::string(std::string s) {
  Value r;
  r.type = ValueType::String;
  r.str = std::make_shared<const std::string>(std::move(s));
  return r;
}

int Value::terms() const {
  switch (type) {
    case ValueType::Float:
      return 1;
    case ValueType::Uv:
      return 2;
    case ValueType::Vector:
      return 3;
    case ValueType::Vector4:
      return 4;
    case ValueType::Colour:
      return 5;
    default:
      return 0;
  }
}

std::string typeName(const Value& v) {
  switch (v.type) {
    case ValueType::Float:
      return "float identifier";
    case ValueType::Uv:
      return "uv vector identifier";
    case ValueType::Vector:
      return "vector identifier";
    case ValueType::Vector4:
      return "4d-vector identifier";
    case ValueType::Colour:
      return "color identifier";
    case ValueType::String:
      return "string identifier";
    case ValueType::Array:
      return "array identifier";
    case ValueType::Item:
      return std::string(v.item ? v.item->kind() : "item") + " identifier";
    case ValueType::Function:
      return "function identifier";
    case ValueType::Spline:
      return "spline identifier";
  }
  return "identifier";
}

std::shared_ptr<ArrayValue> ArrayValue::clone() const {
  auto a = std::make_shared<ArrayValue>(*this);
  for (auto& e : a->elements)
    if (e && e->array) e->array = e->array->clone();
  return a;
}

Value copyValue(const Value& v) {
  Value r = v;
  if (r.array) r.array = r.array->clone();
  return r;
}

}  // namespace lucent::sdl
