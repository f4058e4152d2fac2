#include "expansion.h"

#include <fmt/format.h>

#include <algorithm>

namespace lucent {

namespace {

// The <param> children of `element`, checked; a name given twice in one element is an error.
std::vector<LocalParam> collectParams(ParseContext& ctx, const SourceFile& file,
                                      pugi::xml_node element) {
  std::vector<LocalParam> params;
  for (pugi::xml_node c = element.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element || std::string_view(c.name()) != "param") continue;
    ElementReader r(ctx, file, c);
    r.checkAttributes({"name", "value"});
    r.forEachChild([&](pugi::xml_node n) {
      ElementReader(ctx, file, n)
          .error("<param> takes no child elements, got <" + std::string(n.name()) + ">");
    });
    if (!r.has("name") || !r.has("value")) {
      r.error("<param> needs 'name' and 'value'");
      continue;
    }
    std::string_view name = c.attribute("name").value();
    if (!Parameters::isValidName(name)) {
      r.attrError("name",
                  "a parameter name is letters, digits and '_', not starting with a digit; got '" +
                      std::string(name) + "'");
      continue;
    }
    auto same = std::find_if(params.begin(), params.end(),
                             [&](const LocalParam& p) { return p.name == name; });
    if (same != params.end()) {
      r.attrError("name", "'" + std::string(name) + "' is already declared in this <" +
                              element.name() + "> (at " + file.loc(same->element).str() + ")");
      continue;
    }
    LocalParam p;
    p.name = name;
    p.raw = c.attribute("value").value();
    p.file = &file;
    p.element = c;
    params.push_back(std::move(p));
  }
  return params;
}

constexpr double kEstimateCap = 1e18;

double estimateChildren(ParseContext& ctx, pugi::xml_node element, const ScopePtr& scope,
                        int depth);

// How many nodes a <repeat> makes, judged from its first instance: a cheap upper bound for
// uniform bodies, so that a repeat of 10^6 inside a repeat of 10^6 is refused before anything
// is made. Counts it cannot evaluate here (they use a parameter of the body) count as 1; the
// running count (countNode) is the backstop.
double estimateRepeat(ParseContext& ctx, pugi::xml_node repeat, const ScopePtr& scope, int depth) {
  SubstitutionError error;
  double n = 1;
  if (auto text = ctx.params.substitute(repeat.attribute("count").value(), scope.get(), error))
    if (Parsed<long long> v = parseInteger(*text); v && *v >= 0) n = static_cast<double>(*v);
  auto s = std::make_shared<Scope>();
  s->parent = scope;
  s->var = repeat.attribute("var").value();
  s->file = nullptr;
  s->element = repeat;
  return std::min(kEstimateCap, n * (1.0 + estimateChildren(ctx, repeat, s, depth + 1)));
}

double estimateChildren(ParseContext& ctx, pugi::xml_node element, const ScopePtr& scope,
                        int depth) {
  if (depth > kMaxElementDepth) return 0;
  double sum = 0;
  for (pugi::xml_node c = element.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element) continue;
    std::string_view n = c.name();
    if (n == "param" || n == "material") continue;
    if (n == "repeat") {
      sum += estimateRepeat(ctx, c, scope, depth);
    } else if (n == "if") {
      SubstitutionError error;
      auto text = ctx.params.substitute(c.attribute("test").value(), scope.get(), error);
      Parsed<double> v = text ? parseNumber(*text) : Parsed<double>{};
      if (!text || !v || *v != 0.0) sum += estimateChildren(ctx, c, scope, depth + 1);
    } else {
      sum += 1 + estimateChildren(ctx, c, scope, depth + 1);
    }
    if (sum >= kEstimateCap) return kEstimateCap;
  }
  return sum;
}

// --- Counting ahead ------------------------------------------------------------------
// The outermost <repeat> counts what it will make before making any of it, evaluating its
// counts and tests as the expansion will (quietly: the expansion reports what is wrong),
// and stops counting soon after the limit: a repeat whose inner counts grow with the outer
// variable (count="${i}"), which the estimate from the first instance cannot see, is
// refused before it makes anything. Bodies without <repeat> or <if> are counted once and
// multiplied, so a valid scene pays a small fraction of its expansion for this.

// Is anything under `element` made a varying number of times?
bool varies(pugi::xml_node element) {
  for (pugi::xml_node c = element.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element) continue;
    std::string_view n = c.name();
    if (n == "repeat" || n == "if") return true;
    if (n != "material" && c.first_child() && varies(c)) return true;
  }
  return false;
}

// What the children of an element without repeats or ifs make: one each, with theirs.
long long fixedCount(pugi::xml_node element) {
  long long n = 0;
  for (pugi::xml_node c = element.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element) continue;
    std::string_view name = c.name();
    if (name == "param" || name == "material") continue;
    n += 1 + fixedCount(c);
  }
  return n;
}

// The element's <param>s as a scope, with nothing reported (the expansion checks them).
ScopePtr quietScope(const ParseContext& ctx, const SourceFile& file, pugi::xml_node element,
                    const ScopePtr& parent) {
  (void)ctx;
  ScopePtr s;
  for (pugi::xml_node c = element.child("param"); c; c = c.next_sibling("param")) {
    std::string_view name = c.attribute("name").value();
    if (!Parameters::isValidName(name) || !c.attribute("value")) continue;
    if (!s) {
      s = std::make_shared<Scope>();
      s->parent = parent;
      s->file = &file;
      s->element = element;
    }
    LocalParam p;
    p.name = name;
    p.raw = c.attribute("value").value();
    p.file = &file;
    p.element = c;
    s->params.push_back(std::move(p));
  }
  return s ? s : parent;
}

long long countChildren(ParseContext& ctx, const SourceFile& file, pugi::xml_node element,
                        const ScopePtr& scope, int depth, long long total, long long limit);

// What one element makes, added to `total`.
long long countElement(ParseContext& ctx, const SourceFile& file, pugi::xml_node c,
                       const ScopePtr& scope, int depth, long long total, long long limit) {
  if (depth > kMaxElementDepth || total > limit) return total;
  std::string_view name = c.name();
  if (name == "param" || name == "material") return total;
  SubstitutionError error;
  if (name == "repeat") {
    auto text = ctx.params.substitute(c.attribute("count").value(), scope.get(), error);
    Parsed<long long> n = text ? parseInteger(*text) : Parsed<long long>{};
    if (!n || *n <= 0) return total;
    if (!varies(c)) {
      double made = static_cast<double>(*n) * static_cast<double>(1 + fixedCount(c));
      return made > static_cast<double>(limit - total) ? limit + 1
                                                       : total + static_cast<long long>(made);
    }
    std::string_view var = c.attribute("var").value();
    for (long long i = 0; i < *n && total <= limit; ++i) {
      ++total;
      auto s = std::make_shared<Scope>();
      s->parent = scope;
      s->var = var;
      s->value = static_cast<double>(i);
      s->file = &file;
      s->element = c;
      ScopePtr withParams = quietScope(ctx, file, c, s);
      if (withParams != s) {  // the repeat's own parameters belong to the instance's scope
        s->params = std::move(withParams->params);
      }
      total = countChildren(ctx, file, c, s, depth + 1, total, limit);
    }
    return total;
  }
  ScopePtr inner = quietScope(ctx, file, c, scope);
  if (name == "if") {
    auto text = ctx.params.substitute(c.attribute("test").value(), inner.get(), error);
    Parsed<double> v = text ? parseNumber(*text) : Parsed<double>{};
    if (!v || *v == 0.0) return total;
    return countChildren(ctx, file, c, inner, depth + 1, total, limit);
  }
  ++total;  // a geometry node or a light
  return countChildren(ctx, file, c, inner, depth + 1, total, limit);
}

long long countChildren(ParseContext& ctx, const SourceFile& file, pugi::xml_node element,
                        const ScopePtr& scope, int depth, long long total, long long limit) {
  if (!varies(element)) {
    long long n = fixedCount(element);
    return n > limit - total ? limit + 1 : total + n;
  }
  for (pugi::xml_node c = element.first_child(); c && total <= limit; c = c.next_sibling())
    if (c.type() == pugi::node_element)
      total = countElement(ctx, file, c, scope, depth, total, limit);
  return total;
}

void expandRepeat(ElementReader& parent, pugi::xml_node element, int depth,
                  const std::function<void(pugi::xml_node)>& f) {
  ParseContext& ctx = parent.ctx();
  const SourceFile& file = parent.file();
  ElementReader r(ctx, file, element);
  if (!withinElementDepth(r, depth)) return;
  r.checkAttributes({"var", "count"});
  if (!r.has("var") || !r.has("count")) {
    r.error("<repeat> needs 'var' (the name of its variable) and 'count' (how many instances)");
    return;
  }
  std::string_view var = element.attribute("var").value();
  if (!Parameters::isValidName(var)) {
    r.attrError("var",
                "a variable name is letters, digits and '_', not starting with a digit; got '" +
                    std::string(var) + "'");
    return;
  }
  if (std::string what = ctx.params.whatIs(var, ctx.scope.get()); !what.empty()) {
    r.attrError("var", "'" + std::string(var) + "' is already " + what +
                           "; give the repeat's variable another name");
    return;
  }
  long long count = r.integer("count", -1, 0, kMaxExpandedNodes);
  if (count < 0) return;

  bool outermost = ctx.outerRepeatFile == nullptr;
  if (outermost) {
    double estimate = estimateRepeat(ctx, element, ctx.scope, depth);
    if (static_cast<double>(ctx.nodeCount) + estimate > static_cast<double>(kMaxExpandedNodes)) {
      r.error(fmt::format(
          "this <repeat> would expand the scene to about {:.3g} nodes, lights and repeat "
          "instances, more than the limit of {}",
          static_cast<double>(ctx.nodeCount) + estimate, kMaxExpandedNodes));
      ctx.overLimit = true;
      return;
    }
    {
      Parameters::Quiet quiet(ctx.params);
      long long made =
          countElement(ctx, file, element, ctx.scope, depth, ctx.nodeCount, kMaxExpandedNodes);
      if (made > kMaxExpandedNodes) {
        r.error(fmt::format(
            "this <repeat> would expand the scene to more than {} nodes, lights and repeat "
            "instances (the limit)",
            kMaxExpandedNodes));
        ctx.overLimit = true;
        return;
      }
    }
    ctx.outerRepeatFile = &file;
    ctx.outerRepeat = element;
  }
  for (long long i = 0; i < count; ++i) {
    if (!countNode(ctx)) break;
    auto s = std::make_shared<Scope>();
    s->parent = ctx.scope;
    s->var = var;
    s->value = static_cast<double>(i);
    s->file = &file;
    s->element = element;
    size_t errorsBefore = ctx.diags.errorCount();
    s->params = collectParams(ctx, file, element);
    ScopePtr saved = std::move(ctx.scope);
    ctx.scope = std::move(s);
    forEachExpandedChild(r, depth + 1, f);
    ctx.scope = std::move(saved);
    // One faulty instance says it all: the others would repeat its errors.
    if (ctx.diags.errorCount() > errorsBefore || ctx.overLimit) break;
  }
  if (outermost) ctx.outerRepeatFile = nullptr;
}

void expandIf(ElementReader& parent, pugi::xml_node element, int depth,
              const std::function<void(pugi::xml_node)>& f) {
  ParseContext& ctx = parent.ctx();
  ElementReader r(ctx, parent.file(), element);
  if (!withinElementDepth(r, depth)) return;
  r.checkAttributes({"test"});
  if (!r.has("test")) {
    r.error("<if> needs a 'test' attribute, such as test=\"${i % 2 == 0}\"");
    return;
  }
  LocalScope scope(ctx, parent.file(), element);
  auto text = r.text("test");
  if (!text) return;
  Parsed<double> v = parseNumber(*text);
  if (!v) {
    r.attrError("test", "expected a number (0 is false, anything else true), got '" + *text +
                            "'; write an expression as test=\"${...}\"");
    return;
  }
  if (*v != 0.0) forEachExpandedChild(r, depth + 1, f);
}

}  // namespace

LocalScope::LocalScope(ParseContext& ctx, const SourceFile& file, pugi::xml_node element)
    : ctx_(ctx) {
  ScopePtr overrides = std::move(ctx.instanceParams);  // for the root of an instance only
  ctx.instanceParams = nullptr;
  std::vector<LocalParam> params = collectParams(ctx, file, element);
  if (overrides) {
    for (size_t k = 0; k < overrides->params.size(); ++k) {
      const LocalParam& given = overrides->params[k];
      auto own = std::find_if(params.begin(), params.end(),
                              [&](const LocalParam& p) { return p.name == given.name; });
      if (own == params.end()) {
        params.push_back(given);
        own = params.end() - 1;
      }
      own->aliasScope = overrides;
      own->aliasIndex = k;
    }
  }
  if (params.empty()) return;
  if (std::string_view(element.name()) == "use")
    for (LocalParam& p : params)
      if (!p.aliasScope) {
        p.readOutside = true;
        p.outside = ctx.scope;
      }
  auto s = std::make_shared<Scope>();
  s->parent = ctx.scope;
  s->file = &file;
  s->element = element;
  s->params = std::move(params);
  saved_ = std::move(ctx.scope);
  ctx.scope = std::move(s);
  pushed_ = true;
}

LocalScope::~LocalScope() {
  if (pushed_) ctx_.scope = std::move(saved_);
}

void forEachExpandedChild(ElementReader& r, int depth,
                          const std::function<void(pugi::xml_node)>& f) {
  ParseContext& ctx = r.ctx();
  r.forEachChild([&](pugi::xml_node c) {
    if (ctx.overLimit) return;
    std::string_view n = c.name();
    if (n == "param") return;
    if (n == "repeat" || n == "if") expandElement(r, c, depth, f);
    else f(c);
  });
}

void expandElement(ElementReader& r, pugi::xml_node element, int depth,
                   const std::function<void(pugi::xml_node)>& f) {
  if (std::string_view(element.name()) == "repeat") expandRepeat(r, element, depth, f);
  else expandIf(r, element, depth, f);
}

double estimateNodes(ParseContext& ctx, pugi::xml_node element, const ScopePtr& scope) {
  return std::min(kEstimateCap, 1 + estimateChildren(ctx, element, scope, 0));
}

bool withinElementDepth(ElementReader& r, int depth) {
  if (depth <= kMaxElementDepth) return true;
  r.error("elements nest deeper than " + std::to_string(kMaxElementDepth) + " levels here");
  return false;
}

bool countNode(ParseContext& ctx) {
  if (ctx.overLimit) return false;
  // Only what repeats and instances make counts: a plain scene is as large as its file.
  if (!ctx.outerRepeatFile && ctx.instanceChain.empty()) return true;
  if (++ctx.nodeCount <= kMaxExpandedNodes) return true;
  ctx.overLimit = true;
  SourceLoc where = ctx.outerRepeatFile ? ctx.outerRepeatFile->loc(ctx.outerRepeat)
                                        : SourceLoc{ctx.scene.file, 0, 0};
  ctx.diags.error(
      where,
      fmt::format("the scene expands to more than {} nodes, lights and repeat instances (the "
                  "limit); this <repeat> is where it crosses it",
                  kMaxExpandedNodes));
  return false;
}

}  // namespace lucent
