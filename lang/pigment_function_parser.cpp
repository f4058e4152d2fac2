#include "pigment_function_parser.h"

#include "expression_functions.h"
#include "parameters.h"
#include "texture_parser.h"

#include <algorithm>
#include <string>

namespace lucent {

namespace {

std::vector<std::pair<std::string_view, PigmentComponent>> componentTable() {
  std::vector<std::pair<std::string_view, PigmentComponent>> t;
  for (size_t i = 0; i < std::size(kPigmentComponentNames); ++i)
    t.emplace_back(kPigmentComponentNames[i], static_cast<PigmentComponent>(i));
  return t;
}

bool validName(ElementReader& c, const std::string& name,
               const std::vector<std::shared_ptr<const PigmentFunction>>& before) {
  const auto& functions = expressionFunctionNames();
  if (!Parameters::isValidName(name)) {
    c.attrError("name",
                "'" + name + "' is not a name (a letter or '_', then letters, digits, '_')");
  } else if (name == "x" || name == "y" || name == "z") {
    c.attrError("name", "'" + name + "' is a variable of the function");
  } else if (std::find(functions.begin(), functions.end(), name) != functions.end()) {
    c.attrError("name", "'" + name + "' is a function of the expressions");
  } else {
    for (const auto& p : before)
      if (p->name == name) {
        c.attrError("name", "two <pigment-function>s are named '" + name + "'");
        return false;
      }
    return true;
  }
  return false;
}

}  // namespace

std::vector<std::shared_ptr<const PigmentFunction>> parsePigmentFunctions(ElementReader& r,
                                                                          bool& failed) {
  std::vector<std::shared_ptr<const PigmentFunction>> out;
  for (pugi::xml_node n = r.element().child("pigment-function"); n;
       n = n.next_sibling("pigment-function")) {
    ElementReader c(r.ctx(), r.file(), n);
    c.checkAttributes({"name", "component"});
    auto f = std::make_shared<PigmentFunction>();
    const std::optional<std::string> name = c.text("name");
    if (name) f->name = *name;
    else c.error("<pigment-function> needs a 'name' (how the function calls it)");
    if (!c.has("component"))
      c.error(
          "<pigment-function> needs a 'component' (red, green, blue, filter, transmit, gray or "
          "value)");
    f->component = c.choice("component", PigmentComponent::red, componentTable());
    int textures = 0;
    const std::vector<std::string_view> kinds = textureElements();
    c.forEachChild([&](pugi::xml_node t) {
      ElementReader tr(r.ctx(), r.file(), t);
      const std::string_view kind = t.name();
      ++textures;
      if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end() || kind == "image") {
        tr.error(
            "<pigment-function> holds one texture (<pattern>, <checker>, <hexagon>, "
            "<brick> or <average>), not <" +
            std::string(kind) + ">");
      } else if (textures > 1) {
        tr.error("<pigment-function> holds one texture");
      } else {
        f->pigment = parseTexture(tr);
        refuseUvMapping(tr, f->pigment, "a pigment function, called at a point,");
        if (textureHoldsImage(f->pigment))
          tr.error(
              "a <pigment-function>'s texture holds an <image>, which has no colour at a "
              "point without (u, v)");
      }
      failed = failed || tr.failed();
    });
    if (textures == 0 && !c.failed())
      c.error("<pigment-function> needs a texture child (<pattern>, <checker>...)");
    const auto* pattern = std::get_if<PatternTexture>(&f->pigment);
    if (f->component == PigmentComponent::value && !c.failed() &&
        !(pattern && pattern->pigments.empty()))
      c.attrError("component",
                  "'value' is a <pattern>'s own value: the texture must be a <pattern> (without a "
                  "<pigment-map>)");
    if (name && validName(c, *name, out) && !c.failed()) out.push_back(std::move(f));
    failed = failed || c.failed();
  }
  return out;
}

}  // namespace lucent
