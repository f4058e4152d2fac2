// After every element is read: <use ref> is resolved against node ids, reference cycles
// (a node that contains itself through <use>) are found, the nesting depth through <use>
// is limited, and the operands of merge, intersection and difference are checked to be
// solids (which needs the references resolved, since a <use> is as solid as its target).
#include "element_parsers.h"
#include "expansion.h"
#include "scenegraph/flatten.h"
#include "scenegraph/located_error.h"
#include "scenegraph/shape_registry.h"

#include <fmt/format.h>

#include <algorithm>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace lucent {

namespace {

std::string useLabel(const Node& n) {
  return n.target ? "<use ref=\"" + n.target->id + "\">" : "<use>";
}

// A light's <projected-through>, or null.
const Node* projectedThrough(const Node& n) {
  return n.kind == NodeKind::Light && n.light ? n.light->projectedThrough.get() : nullptr;
}

// Everything a node leads to: its children, or the target of a <use>, the solids of its
// <clip> and <bound>, and a light's <projected-through>.
std::vector<const Node*> successors(const Node& n) {
  std::vector<const Node*> out;
  if (n.kind == NodeKind::Use) {
    if (n.target) out.push_back(n.target);
  } else {
    for (const auto& c : n.children) out.push_back(c.get());
  }
  for (const auto& c : n.clip) out.push_back(c.get());
  for (const auto& c : n.bound) out.push_back(c.get());
  if (const Node* through = projectedThrough(n)) out.push_back(through);
  return out;
}

// Depth-first search over the node graph without recursion (a chain of 100,000 <use>s
// must not overflow the stack). Reports every back edge (a cycle) and computes each
// node's depth: 1 + the deepest thing it leads to.
class GraphWalk {
 public:
  explicit GraphWalk(ParseContext& ctx) : ctx_(ctx) {}

  void walk(const Node& start) {
    if (state_.count(&start)) return;
    struct Frame {
      const Node* node;
      std::vector<const Node*> next;
      size_t i = 0;
      int depth = 1;
    };
    std::vector<Frame> stack;
    auto push = [&](const Node* n) {
      state_[n] = kActive;
      stack.push_back({n, successors(*n)});
    };
    push(&start);
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.i < f.next.size()) {
        const Node* s = f.next[f.i++];
        auto it = state_.find(s);
        if (it == state_.end()) {
          push(s);
        } else if (it->second == kActive) {
          reportCycle(stack, *f.node, *s);
        } else {
          f.depth = std::max(f.depth, 1 + depth_[s]);
        }
        continue;
      }
      const Node* done = f.node;
      int depth = f.depth;
      state_[done] = kDone;
      depth_[done] = depth;
      stack.pop_back();
      if (!stack.empty()) stack.back().depth = std::max(stack.back().depth, 1 + depth);
    }
  }

  int depth(const Node& n) const {
    auto it = depth_.find(&n);
    return it == depth_.end() ? 0 : it->second;
  }
  // Every node reached, in the order first seen.
  template <class F>
  void forEachNode(F f) const {
    for (const auto& [n, s] : state_) f(*n);
  }

 private:
  enum State { kActive, kDone };

  template <class Stack>
  void reportCycle(const Stack& stack, const Node& from, const Node& target) {
    // The path from the target down to `from`, named by the ids the <use>s refer to.
    std::string chain = target.id.empty() ? "<" + target.element + ">" : "'" + target.id + "'";
    bool inside = false;
    for (const auto& f : stack) {
      if (f.node == &target) inside = true;
      if (inside && f.node->kind == NodeKind::Use && f.node->target)
        chain += " -> '" + f.node->target->id + "'";
    }
    ctx_.diags.error(from.loc, useLabel(from) + " creates a reference cycle: " + chain +
                                   " (a node cannot contain itself)");
    ctx_.broken.insert(&from);
  }

  ParseContext& ctx_;
  std::unordered_map<const Node*, State> state_;
  std::unordered_map<const Node*, int> depth_;
};

// The first leaf (or empty group) that keeps `n` from being a solid, mirroring
// Node::isSolid(); null if n is a solid. Broken <use>s are not followed: every reference
// cycle has one (the DFS back edge), so the recursion ends, within kMaxInstanceDepth.
const Node* findNonSolid(const ParseContext& ctx, const Node& n) {
  switch (n.kind) {
    case NodeKind::Shape:
      return n.shape && isSolid(*n.shape) ? nullptr : &n;
    case NodeKind::Use:
      return n.target && !ctx.broken.count(&n) ? findNonSolid(ctx, *n.target) : nullptr;
    case NodeKind::Merge:
    case NodeKind::Intersection:
    case NodeKind::Difference:
    case NodeKind::Light:
      return nullptr;  // a light is no operand: it neither adds nor spoils
    case NodeKind::Union:
    case NodeKind::Group:
      if (n.children.empty()) return &n;
      for (const auto& c : n.children)
        if (const Node* o = findNonSolid(ctx, *c)) return o;
      return nullptr;
  }
  return nullptr;
}

std::string whyNotSolid(const Node& leaf) {
  if (leaf.kind != NodeKind::Shape || !leaf.shape) return "it is empty";
  return lucent::whyNotSolid(*leaf.shape);
}

void checkCsgOperands(ParseContext& ctx, const Node& csg) {
  for (const auto& child : csg.children) {
    if (ctx.broken.count(child.get())) continue;
    const Node* leaf = findNonSolid(ctx, *child);
    if (!leaf || ctx.broken.count(leaf)) continue;
    std::string what = child->kind == NodeKind::Use ? useLabel(*child) : "<" + child->element + ">";
    std::string message = what + " cannot be an operand of <" + csg.element + "> (at " +
                          csg.loc.str() + "), which needs solids: ";
    if (leaf == child.get()) message += "it is not a solid (" + whyNotSolid(*leaf) + ")";
    else
      message += "it contains <" + leaf->element + "> at " + leaf->loc.str() +
                 ", which is not a solid (" + whyNotSolid(*leaf) + ")";
    ctx.diags.error(child->loc, message);
  }
}

// What a <clip> or <bound> holds must have an inside: a clip keeps the points inside it.
void checkClipSolids(ParseContext& ctx, const Node& owner,
                     const std::vector<std::unique_ptr<Node>>& solids, const char* what) {
  for (const auto& child : solids) {
    if (ctx.broken.count(child.get())) continue;
    const Node* leaf = findNonSolid(ctx, *child);
    if (!leaf || ctx.broken.count(leaf)) continue;
    std::string label =
        child->kind == NodeKind::Use ? useLabel(*child) : "<" + child->element + ">";
    std::string message = label + " in the <" + std::string(what) + "> of <" + owner.element +
                          "> (at " + owner.loc.str() + ") must be a solid: ";
    if (leaf == child.get()) message += "it is not one (" + whyNotSolid(*leaf) + ")";
    else
      message += "it contains <" + leaf->element + "> at " + leaf->loc.str() +
                 ", which is not a solid (" + whyNotSolid(*leaf) + ")";
    ctx.diags.error(child->loc, message);
  }
}

// inverse="true" swaps a solid's inside and outside: a surface without one cannot have it.
void checkInverse(ParseContext& ctx, const Node& n) {
  if (ctx.broken.count(&n)) return;
  const Node* leaf = findNonSolid(ctx, n);
  if (!leaf || ctx.broken.count(leaf)) return;
  std::string message = "<" + n.element + "> inverse=\"true\" needs a solid: ";
  if (leaf == &n) message += "it is not one (" + whyNotSolid(*leaf) + ")";
  else
    message += "it contains <" + leaf->element + "> at " + leaf->loc.str() +
               ", which is not a solid (" + whyNotSolid(*leaf) + ")";
  ctx.diags.error(n.loc, message);
}

// A <use> with <param>s: its target's element is read again in the scope it was written in,
// with the <use>'s parameters hiding the target's own, and the copy becomes the <use>'s one
// child (the <use> turns into a group). Instances may hold more of them: the list grows
// while it is worked through. A definition that uses itself, even through others, is an
// error; the chain of definitions makes that a check, not a stack overflow.
void instantiate(ParseContext& ctx) {
  std::vector<std::string_view> ids;
  // A definition is read by itself and again for each parameterised <use> of it: a faulty
  // <use> inside it gives the same error each time, so it is reported once.
  std::unordered_set<std::string> reported;
  auto reportOnce = [&](const SourceLoc& loc, std::string message) {
    if (reported.insert(loc.str() + '\n' + message).second)
      ctx.diags.error(loc, std::move(message));
  };
  // What the instances not made yet will make, estimated from their definitions as each
  // joins the list: a <repeat> of a million parameterised uses of a large definition is
  // refused before the first copy, not after 10^7 nodes (the running count stays the
  // backstop for what the estimate cannot see, such as counts given by the <use>).
  std::vector<double> estimates;
  double pending = 0;
  for (size_t k = 0; k < ctx.instances.size() && !ctx.overLimit; ++k) {
    for (size_t e = estimates.size(); e < ctx.instances.size(); ++e) {
      const ParseContext::PendingInstance& next = ctx.instances[e];
      auto target = ctx.nodeIds.find(next.ref);
      if (target == ctx.nodeIds.end()) {
        estimates.push_back(0.0);
        continue;
      }
      // In the scope the copy will have, so that counts given by the <use>'s parameters
      // count; quietly, since reading the copy reports what is wrong.
      ScopePtr scope = target->second.scope;
      if (next.scope && !next.scope->params.empty()) {
        auto s = std::make_shared<Scope>();
        s->parent = scope;
        s->file = target->second.file;
        s->element = target->second.element;
        for (size_t i = 0; i < next.scope->params.size(); ++i) {
          LocalParam given = next.scope->params[i];
          given.aliasScope = next.scope;
          given.aliasIndex = i;
          s->params.push_back(std::move(given));
        }
        scope = std::move(s);
      }
      Parameters::Quiet quiet(ctx.params);
      estimates.push_back(estimateNodes(ctx, target->second.element, scope));
      pending += estimates.back();
    }
    if (static_cast<double>(ctx.nodeCount) + pending > static_cast<double>(kMaxExpandedNodes)) {
      ctx.diags.error(
          ctx.instances[k].use->loc,
          fmt::format(
              "the <use>s with parameters would expand the scene to about {:.3g} nodes, lights "
              "and repeat instances, more than the limit of {}; this <use> is the first of "
              "those not made yet",
              static_cast<double>(ctx.nodeCount) + pending, kMaxExpandedNodes));
      ctx.overLimit = true;
      break;
    }
    pending -= estimates[k];
    ParseContext::PendingInstance u = ctx.instances[k];
    auto it = ctx.nodeIds.find(u.ref);
    if (it == ctx.nodeIds.end()) {
      if (ids.empty()) {
        for (const auto& [id, entry] : ctx.nodeIds) ids.push_back(id);
        std::sort(ids.begin(), ids.end());
      }
      reportOnce(u.refLoc, "<use> attribute 'ref': no node has the id '" + u.ref + "'" +
                               didYouMean(u.ref, ids));
      ctx.broken.insert(u.use);
      continue;
    }
    if (std::find(u.chain.begin(), u.chain.end(), u.ref) != u.chain.end()) {
      std::string chain;
      for (const std::string& c : u.chain) chain += "'" + c + "' -> ";
      reportOnce(u.use->loc, "<use ref=\"" + u.ref + "\"> instantiates '" + u.ref +
                                 "' inside its own definition: " + chain + "'" + u.ref +
                                 "' (a definition cannot use itself)");
      ctx.broken.insert(u.use);
      continue;
    }
    const ParseContext::IdEntry target = it->second;
    ScopePtr savedScope = std::move(ctx.scope);
    std::vector<std::string> savedChain = std::move(ctx.instanceChain);
    bool savedRegister = ctx.registerIds;
    ctx.scope = target.scope;
    ctx.instanceChain = u.chain;
    ctx.instanceChain.push_back(u.ref);
    ctx.instanceParams = u.scope;
    ctx.registerIds = false;
    std::unique_ptr<Node> copy = parseGeometryNode(ctx, *target.file, target.element, 2);
    ctx.scope = std::move(savedScope);
    ctx.instanceChain = std::move(savedChain);
    ctx.instanceParams = nullptr;
    ctx.registerIds = savedRegister;
    if (!copy) {
      ctx.broken.insert(u.use);
      continue;
    }
    if (ctx.broken.count(copy.get())) ctx.broken.insert(u.use);
    u.use->kind = NodeKind::Group;
    u.use->children.push_back(std::move(copy));
  }
}

// Each object pattern's node, which must be a solid (the pattern is its inside), and its
// solid built once. Its materials play no part, so a node may wear a pattern of itself.
void resolveObjectPatterns(ParseContext& ctx) {
  std::vector<std::string_view> ids;
  for (const ParseContext::PendingObjectPattern& p : ctx.objectPatterns) {
    const std::string prefix = p.tag + " attribute 'object': ";
    auto it = ctx.nodeIds.find(p.pattern->id);
    if (it == ctx.nodeIds.end()) {
      if (ids.empty()) {
        for (const auto& [id, entry] : ctx.nodeIds) ids.push_back(id);
        std::sort(ids.begin(), ids.end());
      }
      ctx.diags.error(p.loc, prefix + "no node has the id '" + p.pattern->id + "'" +
                                 didYouMean(p.pattern->id, ids));
      continue;
    }
    const Node& node = *it->second.node;
    if (ctx.broken.count(&node)) continue;
    if (node.isLight()) {
      ctx.diags.error(p.loc, prefix + "'" + p.pattern->id + "' (at " + node.loc.str() +
                                 ") is a light; an object pattern needs a solid");
      continue;
    }
    if (const Node* leaf = findNonSolid(ctx, node)) {
      if (ctx.broken.count(leaf)) continue;
      std::string message = prefix + "'" + p.pattern->id + "' (<" + node.element + "> at " +
                            node.loc.str() + ") has no inside, which an object pattern needs: ";
      if (leaf == &node) message += "it is not a solid (" + whyNotSolid(*leaf) + ")";
      else
        message += "it contains <" + leaf->element + "> at " + leaf->loc.str() +
                   ", which is not a solid (" + whyNotSolid(*leaf) + ")";
      ctx.diags.error(p.loc, message);
      continue;
    }
    p.pattern->node = &node;
    if (ctx.diags.hasErrors()) continue;  // a reference cycle would not end
    try {
      p.pattern->solid = buildSolid(ctx.scene, node, makeShape);
      if (!p.pattern->solid)
        ctx.diags.error(p.loc, prefix + "'" + p.pattern->id + "' (at " + node.loc.str() +
                                   ") holds no shape; an object pattern needs a solid");
    } catch (const LocatedError& e) {
      ctx.diags.error(e.loc(), e.message());
    }
  }
}

}  // namespace

void resolveReferences(ParseContext& ctx) {
  instantiate(ctx);
  // 1. Every <use ref> names a node. A <use> inside a <repeat> is one element made many
  // times: a wrong ref there is one error, not one per instance (as the repeat would stop
  // at its first faulty instance had the ref been known then).
  std::vector<std::string_view> ids;
  std::unordered_set<std::string> reported;
  for (const ParseContext::PendingUse& u : ctx.uses) {
    auto it = ctx.nodeIds.find(u.ref);
    if (it != ctx.nodeIds.end()) {
      u.use->target = it->second.node;
      continue;
    }
    ctx.broken.insert(u.use);
    if (!reported.insert(u.refLoc.str() + '\n' + u.ref).second) continue;
    if (ids.empty()) {
      for (const auto& [id, entry] : ctx.nodeIds) ids.push_back(id);
      std::sort(ids.begin(), ids.end());
    }
    ctx.diags.error(u.refLoc, "<use> attribute 'ref': no node has the id '" + u.ref + "'" +
                                  didYouMean(u.ref, ids));
  }

  // 3. merge, intersection and difference combine solids only, and only a solid can be
  // inverse. Checked in source order.
  std::vector<const Node*> csgNodes;
  auto isCsgOperation = [](const Node& n) {
    return n.kind == NodeKind::Merge || n.kind == NodeKind::Intersection ||
           n.kind == NodeKind::Difference || n.inverse;
  };
  if (ctx.uses.empty()) {
    // Without <use> references the nodes form a tree (no cycles, and no deeper than the
    // elements nest): a plain walk finds the CSG operations, with no map over every node.
    // Parameterised uses nest copies in copies, so the depth is still checked.
    std::vector<std::pair<const Node*, int>> stack;
    stack.emplace_back(ctx.scene.root.get(), 1);
    for (const auto& d : ctx.scene.defs) stack.emplace_back(d.get(), 1);
    while (!stack.empty()) {
      auto [n, depth] = stack.back();
      stack.pop_back();
      if (depth > kMaxInstanceDepth) {
        ctx.diags.error(n->loc, "<" + n->element + "> nests deeper than " +
                                    std::to_string(kMaxInstanceDepth) +
                                    " levels, counting what the <use>s around it instantiate");
        return;
      }
      if (isCsgOperation(*n)) csgNodes.push_back(n);
      for (const auto& c : n->children) stack.emplace_back(c.get(), depth + 1);
      for (const auto& c : n->clip) stack.emplace_back(c.get(), depth + 1);
      for (const auto& c : n->bound) stack.emplace_back(c.get(), depth + 1);
      if (const Node* through = projectedThrough(*n)) stack.emplace_back(through, depth + 1);
    }
  } else {
    // 2. No node contains itself, and nothing nests too deep through <use>.
    GraphWalk walk(ctx);
    walk.walk(*ctx.scene.root);
    for (const auto& d : ctx.scene.defs) walk.walk(*d);
    // Depths ignore the back edges of cycles (reported above), so they are finite.
    bool tooDeep = false;
    auto checkDepth = [&](const Node& top) {
      if (!tooDeep && walk.depth(top) > kMaxInstanceDepth) {
        ctx.diags.error(top.loc, "<" + top.element + "> nests deeper than " +
                                     std::to_string(kMaxInstanceDepth) +
                                     " levels, counting what its <use>s instantiate");
        tooDeep = true;
      }
    };
    for (const auto& c : ctx.scene.root->children) checkDepth(*c);
    for (const auto& d : ctx.scene.defs) checkDepth(*d);
    if (tooDeep) return;
    walk.forEachNode([&](const Node& n) {
      if (isCsgOperation(n)) csgNodes.push_back(&n);
    });
  }
  std::sort(csgNodes.begin(), csgNodes.end(), [](const Node* a, const Node* b) {
    return std::tie(a->loc.file, a->loc.line, a->loc.col) <
           std::tie(b->loc.file, b->loc.line, b->loc.col);
  });
  for (const Node* n : csgNodes) {
    if (n->inverse) checkInverse(ctx, *n);
    if (n->kind == NodeKind::Merge || n->kind == NodeKind::Intersection ||
        n->kind == NodeKind::Difference)
      checkCsgOperands(ctx, *n);
  }
  for (const Node* n : ctx.clipped) {
    checkClipSolids(ctx, *n, n->clip, "clip");
    checkClipSolids(ctx, *n, n->bound, "bound");
  }
  resolveObjectPatterns(ctx);
}

}  // namespace lucent
