// Quadrics from shapes_old.inc (the ones shapes.inc declares), a quadric and a quartic
// written out, the terms odd in z among them: the z negation of each coefficient shows.
#version 3.7;
#include "shapes_old.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> right x*4/3 look_at <0, 0.3, 0> angle 55 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { rgb 0.7 } }
object { Ellipsoid scale <0.9, 0.5, 0.6> rotate y*30 translate <-2.2, 0, 0.5>
         pigment { rgb <0.9, 0.3, 0.2> } }
intersection { object { Paraboloid_Y } plane { y, 1 } scale 0.7 rotate <-30, 0, 20>
               translate <2.2, 0, 0.5> pigment { rgb <0.2, 0.4, 0.9> } }
intersection {
  quadric { <1, 0, 1>, <0, 0.8, 0.5>, <0, 0, 0.4>, -0.3 }
  box { <-1, -1, -1>, <1, 1, 1> }
  pigment { rgb <0.3, 0.8, 0.3> } rotate x*-20 translate <0, 0, 1.2>
}
// A torus as a quartic (R = 0.6, r = 0.2), tipped towards the camera.
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -0.8, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 0.64, 0, 0, 0, 0, 1, 0, -0.8, 0, 0.1024>
          sturm rotate x*-50 rotate y*20 translate <0.3, 0.1, -1.6> pigment { rgb <0.9, 0.8, 0.2> } }
