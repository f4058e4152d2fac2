// The finish table: the finish and interior terms of <material>, one row per attribute,
// beside the Material they are read into (material.h). Derived from it: the parser's
// attribute list and reads (lang/material_parser.cpp), the schema's materialAttributes
// (lang/schema.cpp), the hints for POV-Ray's words written on a <material>
// (lang/povray_names.cpp) and the finish keywords POV-Ray has as they are
// (povray/pov_materials.cpp). The shading of the terms is render/finish.cpp's. How to add a
// term: docs/architecture.md, "The finish table".
#pragma once

#include "attribute_info.h"
#include "material.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// The exporter's side of writing a term's POV-Ray finish lines (povray/pov_materials.cpp
// implements it).
class PovFinishOut {
 public:
  virtual ~PovFinishOut() = default;
  virtual void line(std::string_view text) = 0;
  virtual std::string number(double v) const = 0;  // POV-Ray's number syntax, read back exactly
};

// A POV-Ray word a user may write on a <material> by habit, answered by a hint that names
// the term's attribute followed by `note`: " (POV-Ray's 'roughness' is 'shininess'
// (1/roughness) in Lucent)".
struct PovHint {
  std::string_view word;
  std::string_view note = {};
};

struct FinishTerm {
  AttributeInfo info;
  // Stores the attribute into the material when it is written; an absent one leaves the
  // material's value (the default, or its base material's).
  std::function<void(Material&, AttributeInput&)> read;
  // Where POV-Ray 3.7 has the term, for readers: "finish { phong_size }".
  std::string_view pov;
  std::vector<PovHint> povHints;
  // The term's POV-Ray finish lines when POV-Ray has it as it is; null when the exporter
  // converts it together with other terms (POV-Ray's pigment carries the diffuse colour,
  // its opacity scales the local terms: povray/pov_materials.h) or another row writes it.
  std::function<void(const Material&, PovFinishOut&)> writePov;
  // A term of the whole material (its interior: ior, fade, absorption, hollow, full-tir,
  // inner-ambient), which a <layer> does not take.
  bool ofInterior = false;
};

// Every finish and interior attribute of <material>, in the schema's order, which is also
// the order they are read in (and so of their messages). The structural attributes (id,
// base, default) and the children are the parser's.
const std::vector<FinishTerm>& finishTerms();

}  // namespace lucent
