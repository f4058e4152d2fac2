// A scene's <rainbow> (docs/scene-language.md, "<rainbow>"): POV-Ray's rainbow, a colour
// map laid in a ring of angles around the antisolar direction over every ray that runs
// outside solids, faded by the distance to what the ray meets. A scene may have several;
// where rays meet more than one, their effects are averaged, as in POV-Ray.
#pragma once

#include "pattern.h"
#include "source_loc.h"

#include "primitives/math.h"

namespace lucent {

struct Rainbow {
  SourceLoc loc;
  // The antisolar direction (the ring's centre, away from the sun) and the up direction
  // the arc is measured from, as written (not zero, not along each other).
  Vec3 direction{0.0, 0.0, 1.0};
  Vec3 up{0.0, 1.0, 0.0};
  // From them (setFrame): unit vectors along the direction, up made square to it, and
  // right = up × direction.
  Vec3 axis{0.0, 0.0, 1.0};
  Vec3 upAxis{0.0, 1.0, 0.0};
  Vec3 rightAxis{1.0, 0.0, 0.0};
  // Sets the unit vectors from direction and up, as POV-Ray's Parse_Rainbow makes them.
  void setFrame() {
    axis = glm::normalize(direction);
    rightAxis = glm::normalize(glm::cross(glm::normalize(up), axis));
    upAxis = glm::normalize(glm::cross(axis, rightAxis));
  }
  // The ring in degrees as written: its middle's angle from the direction and its width;
  // the colour map runs across it from angle − width/2 (0) to angle + width/2 (1).
  double angle = 0.0;
  double width = 1.0;  // > 0
  // A stretch of length t keeps exp(−t/distance) of the colour at its end.
  double distance = 1e7;
  // The map's value is moved by up to ± this at random per ray.
  double jitter = 0.0;
  // The part of the ring drawn: within arcAngle/2 of up (degrees, 0 to 360); from
  // falloffAngle/2 on it fades out (falloffAngle ≤ arcAngle), as POV-Ray's arc_angle and
  // falloff_angle.
  double arcAngle = 360.0;
  double falloffAngle = 360.0;
  ColorMap map;
};

}  // namespace lucent
