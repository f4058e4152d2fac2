// A sphere on a plane, written as POV-Ray users write it: colors.inc, a camera with
// look_at and the image's aspect ratio, one light.
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1.5, -5>
  right x*image_width/image_height
  look_at <0, 0.8, 0>
}
light_source { <-5, 8, -6> color White }
sphere { <0, 1, 0>, 1
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { phong 0.6 phong_size 40 }
}
plane { y, 0 pigment { color Gray70 } }
