// The curve types of POV-Ray's lathe (primitives/lathe.h says which points each one takes).
#pragma once

namespace lucent {

enum class LatheSpline { Linear, Quadratic, Cubic, Bezier };

}  // namespace lucent
