// Planes whose normal is not of length 1: POV-Ray makes the normal unit and keeps the
// distance (plane { <0, 2, 0>, 0.4 } lies at y = 0.4, not 0.2), alone and in an intersection.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <3, 4, -6> look_at <0, 0.3, 0> angle 45 }
light_source { <-3, 6, -5> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { <0, 2, 0>, 0.4 pigment { checker rgb 0.8 rgb 0.5 } }
sphere { <-1.2, 0, 0>, 0.9 pigment { rgb <0.2, 0.8, 0.2> } }
intersection {
  box { -1, 1 pigment { rgb 1 } }
  plane { <0, 1, -1>, 0.7 pigment { rgb <1, 0.2, 0.1> } }
  translate <1.2, 1.2, 0>
}
