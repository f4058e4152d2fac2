// The names visible at one place of a scene while it is expanded (contract, "Local
// parameters" and "<repeat>"): the <param> children of enclosing elements and the variables
// of enclosing <repeat>s, innermost first, in front of the top-level parameters
// (parameters.h). Scopes are shared: a <use> with parameters and a node that a <use> may
// instantiate later keep the scope they were written in alive.
#pragma once

#include "source_file.h"

#include <pugixml.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lucent {

struct Scope;
using ScopePtr = std::shared_ptr<Scope>;

// A <param> child of an element; its value is substituted when first used.
struct LocalParam {
  enum class State { Unresolved, Resolving, Resolved, Failed };
  std::string_view name;  // into the scene text, which outlives the expansion
  std::string_view raw;
  const SourceFile* file = nullptr;
  pugi::xml_node element;  // the <param>, for messages
  State state = State::Unresolved;
  std::string value;
  // The value as one number: 0 not looked at yet, 1 a number, 2 not one number.
  int numberState = 0;
  double number = 0.0;
  // A <use>'s parameter handed to the instance it makes: the entry of the <use>'s own scope
  // that gives the value (read where the <use> stands). Null for an ordinary parameter.
  ScopePtr aliasScope;
  size_t aliasIndex = 0;
  // A <use>'s parameters are arguments: their values are read in the scope around the
  // <use> (`size="${size * 2}"` doubles the size seen there), not among themselves.
  bool readOutside = false;
  ScopePtr outside;  // may be null: the top level
};

struct Scope {
  ScopePtr parent;  // null: the top level
  // A <repeat>'s variable and its value in this instance (var empty: not a repeat).
  std::string_view var;
  double value = 0.0;
  const SourceFile* file = nullptr;
  pugi::xml_node element;  // the <repeat>, or the element whose <param>s these are
  std::vector<LocalParam> params;
};

// " (in the instance i = 3, j = 0 of the <repeat>s at 4:3, 5:5)" for a message about an
// element read inside repeats; "" outside them.
std::string instanceNote(const Scope* scope);

}  // namespace lucent
