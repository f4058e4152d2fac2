// POV-Ray's words that its users write in a Lucent scene by habit (`location`,
// `light_source`, `pigment`...), each pointing at Lucent's word. One table, read by the
// checks of attributes and elements, so every place that says "unknown" says the same.
#pragma once

#include <string>
#include <string_view>

namespace lucent {

// " (POV-Ray's 'location' is 'position' in Lucent)" for an unknown attribute `attribute`
// of the element `element`, or "" if POV-Ray has no such word there.
std::string povrayAttributeHint(std::string_view element, std::string_view attribute);

// The same for an unknown element `child` inside `parent` ("scene" at the top level).
std::string povrayElementHint(std::string_view parent, std::string_view child);

}  // namespace lucent
