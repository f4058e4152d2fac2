// CSG of objects without an inside, as POV-Ray keeps it (its Inside of them is always
// false, even inverted): a triangle cut round by a sphere (intersection), a triangle minus
// a box, a box minus a sphere and a polygon (only the polygon's piece inside the box and
// outside the sphere: the box vanishes), a sphere merged with a polygon (the polygon gone
// inside the sphere), and an intersection of two open objects (nothing).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> right x*image_width/image_height look_at <0, 0.3, 0> angle 48 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1.2 pigment { rgb 0.6 } }
intersection {
  triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }
  sphere { <0.4, 0, 0>, 0.8 }
  pigment { rgb <1, 0.8, 0.5> }
  translate <-3, 1.5, 0>
}
difference {
  triangle { <-0.9, -0.8, 0>, <0.9, -0.8, 0>, <0, 0.9, 0> }
  box { <0, 0, -1>, <1, 1, 1> }
  pigment { rgb <0.5, 0.8, 1> }
  translate <-0.8, 1.5, 0>
}
difference {
  box { -0.8, 0.8 }
  sphere { <0, 0.8, -0.8>, 1 }
  polygon { 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> rotate x*90 translate y*0.1
            pigment { rgb <1, 0.3, 0.3> } }
  pigment { rgb <0.9, 0.9, 0.8> }
  rotate y*20
  translate <1.6, 1, 0>
}
merge {
  sphere { 0, 0.6 }
  polygon { 5, <-1, -0.5>, <1, -0.5>, <1, 0.5>, <-1, 0.5>, <-1, -0.5> }
  pigment { rgb <0.6, 1, 0.6> }
  rotate y*-30
  translate <-2.5, -0.4, 0>
}
intersection {
  polygon { 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }
  triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }
  pigment { rgb 1 }
  translate <3, -0.3, 0>
}
