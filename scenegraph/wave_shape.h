// How POV-Ray 3.7 shapes a pattern's raw value (pattern.cpp, Evaluate_TPat; texture.cpp:
// cycloidal, Triangle_Wave).
#pragma once

#include "pattern.h"

namespace lucent {

// sin(2π·v), computed as POV-Ray does from the fractional part of v (odd about zero).
double cycloidal(double v);

// 0 → 1 → 0 over each unit of v.
double triangleWave(double v);

// Frequency, phase and wave shape applied to a raw pattern value, as POV-Ray does:
// v·frequency + phase is wrapped with fmod(…, 1.00001) — POV-Ray's own constant, so values
// up to 1.00001 pass unwrapped — unless frequency is 0; a negative result is then wrapped
// into [0, 1) with floor; last the wave shape. Frequency, phase and the poly exponent are
// used in single precision, as POV-Ray stores them.
double shapeValue(double raw, const PatternSpec& spec);

}  // namespace lucent
