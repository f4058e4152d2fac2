#include "gamma_attribute.h"

namespace lucent {

std::optional<GammaCurve> readGammaAttribute(ElementReader& r, const char* attr) {
  const std::optional<std::string> text = r.text(attr);
  if (!text) return std::nullopt;
  if (trim(*text) == "srgb") return GammaCurve{true, 1.0};
  // A word other than srgb is named as a wrong curve, not only as a wrong number.
  if (!parseNumber(*text)) {
    r.attrError(attr, "expected a number above 0, or srgb, got '" + *text + "'");
    return std::nullopt;
  }
  const double power =
      r.number(attr, 1.0, NumberRule::between(0.0, kInf, "a number above 0, or srgb", true));
  return GammaCurve{false, power};
}

}  // namespace lucent
