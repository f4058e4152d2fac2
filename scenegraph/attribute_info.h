// One attribute of an element, as the tables of the scene's concepts declare it (shapes in
// shape_type.h, lights in light.h): what the parser's attribute check and the schema need.
#pragma once

#include "attribute_input.h"

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

enum class AttrType {
  Number,
  Vector,
  Direction,
  Boolean,
  Choice,
  Text,
  NumberList,
  IntegerList,
  File
};

struct AttributeInfo {
  std::string name;
  AttrType type = AttrType::Number;
  NumberRule rule;                        // numbers: the range
  std::vector<std::string_view> choices;  // choices: the words
  std::string defaultText;                // as a user would write it; "" when there is none
  bool required = false;
  std::string doc;    // one or two sentences, for the schema
  int listArity = 1;  // lists: numbers per item (3 for x y z)
  // The schema's simple type when the one AttrType gives is not it ("color", "spotAngle").
  std::string_view schemaType = {};
};

}  // namespace lucent
