// Identifiers and where their values live. POV-Ray keeps a stack of symbol tables: the
// global one, then one per include file being read and one per macro call; a name is
// looked up from the newest table to the oldest. A macro parameter given a lone identifier
// refers to that identifier's value (by reference); anything else is a copy.
#pragma once

#include "source.h"
#include "value.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lucent::sdl {

struct Macro {
  std::string name;
  std::vector<std::string> params;
  SourceFile* file = nullptr;
  size_t bodyStart = 0;       // the first token of the body
  size_t endHash = SIZE_MAX;  // the '#' of its #end
  SourceLoc loc;
};

struct Symbol;

// Where a value lives: an identifier's symbol, or an element of an array.
struct Ref {
  std::shared_ptr<Symbol> symbol;
  std::shared_ptr<ArrayValue> array;
  size_t index = 0;

  bool valid() const { return symbol || array; }
  // The value; nullptr for an array element not yet given one.
  const Value* get() const;
  void set(Value v) const;
};

struct Symbol {
  enum class Kind { Value, Parameter, Macro } kind = Kind::Value;
  Value value;
  Ref target;                    // Parameter: the argument's place
  std::shared_ptr<Macro> macro;  // Macro
};

// One table of names. A name is looked up by a view (a token's text), with no copy made:
// each entry owns its name, and the map's key is a view of it.
class SymbolTable {
 public:
  // The symbol named `name`, or nullptr.
  std::shared_ptr<Symbol>* find(std::string_view name) {
    auto it = map_.find(name);
    return it == map_.end() ? nullptr : &it->second->symbol;
  }
  const std::shared_ptr<Symbol>* find(std::string_view name) const {
    auto it = map_.find(name);
    return it == map_.end() ? nullptr : &it->second->symbol;
  }
  // The place of the symbol named `name`, made (empty) if there is none.
  std::shared_ptr<Symbol>& operator[](std::string_view name) {
    if (auto* s = find(name)) return *s;
    auto e = std::make_unique<Entry>();
    e->name = name;
    const std::string_view key = e->name;
    return map_.emplace(key, std::move(e)).first->second->symbol;
  }
  void erase(std::string_view name) { map_.erase(name); }
  // Every name in the table, in no particular order.
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    out.reserve(map_.size());
    for (const auto& [name, entry] : map_) out.push_back(name);
    return out;
  }

 private:
  struct Entry {
    std::string name;
    std::shared_ptr<Symbol> symbol;
  };
  std::unordered_map<std::string_view, std::unique_ptr<Entry>> map_;
};

}  // namespace lucent::sdl
