// The numeric parameters a scene declares, for the page's sliders: the `<param>` elements at
// the top of an XML scene file whose value is one number (`-D` wins over them, so a slider
// sets its value as `-D name=value` does). POV-Ray scenes have none here: a `#declare` in
// the scene wins over POV-Ray's Declare= (and so over -D).
#pragma once

#include <string>
#include <vector>

namespace lucent::preview {

struct SceneParameter {
  std::string name;
  double declared = 0.0;  // the value the scene gives it
};

// The parameters of the scene file `path` (not of its includes), in the file's order; none
// when the file cannot be read or parsed as XML (the render's load says why).
std::vector<SceneParameter> numericParameters(const std::string& path);

// `text` as one finite number ("1.5", "-2e3"), or false.
bool readNumber(const std::string& text, double& value);

}  // namespace lucent::preview
