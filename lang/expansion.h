// <repeat>, <if> and local <param>s (contract, "Expressions, repeats, conditions,
// parameterised definitions"): expanded while the scene is read, so what comes out is a
// plain scene graph. A <repeat> calls the reader of its children once per instance with a
// scope holding its variable; an <if> calls it when its test is not 0; the <param> children
// of an element become a scope around the element's own attributes and children.
#pragma once

#include "element_reader.h"
#include "parse_context.h"

#include <functional>

namespace lucent {

// Sets ctx.scope to a scope with the <param> children of `element` (and, for the root of an
// instance, the <use>'s parameters, which hide the element's own) for its lifetime; leaves
// ctx.scope alone when there are none.
class LocalScope {
 public:
  LocalScope(ParseContext& ctx, const SourceFile& file, pugi::xml_node element);
  ~LocalScope();
  LocalScope(const LocalScope&) = delete;
  LocalScope& operator=(const LocalScope&) = delete;

 private:
  ParseContext& ctx_;
  ScopePtr saved_;
  bool pushed_ = false;
};

// Calls `f` for each child element of r's element, with <repeat> and <if> children expanded
// (f sees every instance, with ctx.scope set for it) and <param> children skipped (the
// element's LocalScope holds them). Text between elements is reported as by forEachChild.
void forEachExpandedChild(ElementReader& r, int depth,
                          const std::function<void(pugi::xml_node)>& f);

// Expands one <repeat> or <if> element that is a child of r's element.
void expandElement(ElementReader& r, pugi::xml_node element, int depth,
                   const std::function<void(pugi::xml_node)>& f);

// At most how many nodes, lights and repeat instances reading `element` (a geometry node)
// in `scope` makes, judged as for a <repeat> (counts it cannot evaluate there count as 1).
double estimateNodes(ParseContext& ctx, pugi::xml_node element, const ScopePtr& scope);

// False, with an error at the element, when it stands deeper than kMaxElementDepth (a bound
// on recursion, so a deeply nested file cannot exhaust the stack).
bool withinElementDepth(ElementReader& r, int depth);

// Counts one node or light made by the expansion; false (and, once, an error at the outermost
// repeat) when the scene is over kMaxExpandedNodes.
bool countNode(ParseContext& ctx);

}  // namespace lucent
