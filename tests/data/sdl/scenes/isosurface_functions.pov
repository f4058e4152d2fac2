// An isosurface of user functions and functions.inc's closed forms, off-centre in z so
// that the handedness of the import shows.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 2.2, -4.5> right x*image_width/image_height look_at <0, 0.4, 0.5> angle 40 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 3, -2> color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.35> }
plane { y, -0.6 pigment { color rgb <0.8, 0.75, 0.7> } }
#declare Bump = 0.08;
#declare Blob = function(a, b, c, r) { f_sphere(a, b, c, r) + Bump*sin(8*a)*sin(8*b)*sin(8*c) }
#declare Shape = function { min(Blob(x + 0.7, y, z - 0.6, 0.55), f_rounded_box(x - 0.6, y, z + 0.3, 0.15, 0.45, 0.5, 0.35)) }
isosurface {
  function { Shape(x, y, z) }
  contained_by { box { <-1.5, -0.6, -1.0>, <1.3, 0.7, 1.3> } }
  max_gradient 2.5
  pigment { color rgb <0.9, 0.5, 0.2> }
  finish { diffuse 0.7 specular 0.3 }
}
isosurface {
  function { f_torus(x, y, z, 0.35, 0.1) }
  contained_by { sphere { 0, 0.5 } }
  translate <0.3, -0.45, -1.2>
  pigment { color rgb <0.3, 0.6, 0.9> }
}
