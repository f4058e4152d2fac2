// The profile of a surface of revolution (<lathe>, <sor>): its attribute `points`, x y
// pairs with x the radius. Shared by the two rows, which read and check it alike.
#pragma once

#include "scenegraph/attribute_input.h"

#include <optional>
#include <string_view>
#include <vector>

namespace lucent {

// The pairs of `points`, unchecked; nullopt after a located error (the attribute missing,
// not numbers, an odd count). `element`: "lathe" or "sor", for the message.
std::optional<std::vector<Vec2>> readProfilePairs(AttributeInput& in, std::string_view element);
// Whether point i of the profile is finite with x >= 0 (a radius); else a located error.
bool profilePointValid(AttributeInput& in, const Vec2& p, size_t i);

}  // namespace lucent
