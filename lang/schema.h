// The XML Schema of the scene language (docs/lucent.xsd), made from lang/schema_template.xsd
// and the shape registry, so that the schema's shapes and their attributes, types and
// defaults are those the parser reads. `lucent schema` prints it; a test requires the
// committed docs/lucent.xsd to equal it.
#pragma once

#include <string>

namespace lucent {

std::string schemaText();

}  // namespace lucent
