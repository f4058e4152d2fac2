// The working gamma a hand-written POV-Ray scene declares with `assumed_gamma`.
//
// POV-Ray 3.7 computes with the scene's colour numbers as they are and treats the results as
// values encoded with the assumed gamma: its output file holds decode(x) re-encoded with
// File_Gamma. Rendering with File_Gamma equal to assumed_gamma therefore writes the working
// values x themselves, bit for bit what assumed_gamma 1.0 with File_Gamma=1.0 writes (checked
// with povray 3.7.0.10 for 1.8, 2.2 and srgb, with and without #version 3.7). Those are the
// values Lucent computes from the same numbers, which it takes as linear.
#pragma once

#include <string>

namespace lucent {

struct PovAssumedGamma {
  enum class Kind {
    Absent,      // no assumed_gamma in the file (POV-Ray's 3.7 default: 1.0)
    Number,      // assumed_gamma NUMBER (value)
    Srgb,        // assumed_gamma srgb
    Unreadable,  // an expression or identifier, or several different values (problem says)
  };
  Kind kind = Kind::Absent;
  double value = 1.0;
  int line = 0;         // of the (first) assumed_gamma, 1-based
  std::string problem;  // for Unreadable

  // The File_Gamma option value that gives back POV-Ray's working values: "1.0", "2.2",
  // "sRGB". Only for Absent, Number and Srgb.
  std::string fileGamma() const;
  // Is the working gamma other than linear?
  bool nonLinear() const { return kind == Kind::Srgb || (kind == Kind::Number && value != 1.0); }
};

// Finds `assumed_gamma` in POV-Ray source text, outside comments (// and nested /* */) and
// strings. Files the scene #includes are not read.
PovAssumedGamma findAssumedGamma(const std::string& povText);

}  // namespace lucent
