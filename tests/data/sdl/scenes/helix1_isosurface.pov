// functions.inc's f_helix1 in isosurfaces: three circular tubes, and two rounded rectangles
// turned 30 degrees, squashed along the helix (its angle's modulo, cross-sections and turn).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 0.5, -4> look_at <0, 0.4, 0> angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
isosurface {
  function { f_helix1(x, y, z, 3, 4, 0.08, 0.35, 1, 1, 0) }
  contained_by { box { <-0.5, 0, -0.5>, <0.5, 1.2, 0.5> } }
  max_gradient 3
  pigment { rgb <0.9, 0.6, 0.3> }
  translate -x*0.8
}
isosurface {
  function { f_helix1(x, y, z, 2, 3, 0.1, 0.3, 1.5, 0.4, 30) }
  contained_by { box { <-0.5, 0, -0.5>, <0.5, 1.2, 0.5> } }
  max_gradient 4
  pigment { rgb <0.3, 0.6, 0.9> }
  translate x*0.8
}
