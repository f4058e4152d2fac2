#include "scope.h"

#include "expression.h"

namespace lucent {

std::string instanceNote(const Scope* scope) {
  std::string vars, where;
  int repeats = 0;
  for (const Scope* s = scope; s; s = s->parent.get()) {
    if (s->var.empty()) continue;
    std::string v = std::string(s->var) + " = " + formatNumber(s->value);
    std::string at = s->file->loc(s->element).str();
    // Innermost first in the chain; outermost first in the message.
    vars = repeats ? v + ", " + vars : v;
    where = repeats ? at + ", " + where : at;
    ++repeats;
  }
  if (!repeats) return "";
  return " (in the instance " + vars + " of the <repeat>" + (repeats > 1 ? "s" : "") + " at " +
         where + ")";
}

}  // namespace lucent
