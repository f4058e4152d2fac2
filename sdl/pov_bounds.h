// The boxes POV-Ray gives objects, as far as bounded_by needs them: POV-Ray shrinks a
// top-level object's bounding box to its bounds' box when that is smaller, even where it
// then drops the bounds themselves as unnecessary, and its search skips every ray that
// misses the box. The scene reader keeps that cut as a <bound> box (read_objects.cpp).
#pragma once

#include "scenegraph/node.h"

#include "primitives/aabb.h"

#include <functional>

namespace lucent::sdl {

// The node's box in the frame `parentFromWorld` leads from: its shapes' boxes through
// their transforms, joined for unions and groups, met for intersections and clips, the
// first operand's for a difference; unbounded for an inverse node.
// `known` may give the box of a node in its parent's frame instead (a CSG the importer
// rewrote keeps the box of the operation read).
using KnownBox = std::function<const AABB*(const Node&)>;
AABB nodeBox(const Node& node, const Mat4& parent, const KnownBox& known = nullptr);

// POV-Ray's measure of which box is smaller (each side capped at its BOUND_HUGE, so that
// unbounded boxes compare).
double boxVolume(const AABB& box);

}  // namespace lucent::sdl
