// POV-Ray's parametric: the Möbius strip of portfolio/allobjects.pov (precomputed, turned),
// a sphere given by its angles with a uv-mapped checker, and a torus of declared functions
// in a sphere container, tilted (all precomputed: POV-Ray's search is slow without).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> right x*image_width/image_height look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1 pigment { rgb 0.6 } }
parametric {
  function { cos(u) + v*cos(u/2)*cos(u) }
  function { sin(u) + v*cos(u/2)*sin(u) }
  function { v*sin(u/2) }
  <0, -0.3>, <2*pi, 0.3>
  contained_by { box { <-2, -2, -2>, <2, 2, 2> } }
  max_gradient 1.5
  accuracy 0.001
  precompute 14, x, y, z
  pigment { rgb <1, 0.8, 0.5> } finish { specular 0.4 }
  rotate <-60, 33, 0> translate <-2.3, 0.6, 0>
}
parametric {
  function { cos(u)*sin(v) } function { cos(v) } function { sin(u)*sin(v) }
  <0, 0>, <2*pi, pi>
  contained_by { sphere { 0, 1.1 } }
  precompute 12 x, y, z
  pigment { uv_mapping checker rgb <0.9, 0.75, 0.2>, rgb <0.15, 0.3, 0.65> scale <pi/4, pi/4, 1> }
  translate <0.3, 0.2, 0.5>
}
#declare R = 0.8;
#declare TorusX = function(a, b) { (R + 0.3*cos(b))*cos(a) }
#declare TorusZ = function(a, b) { (R + 0.3*cos(b))*sin(a) }
parametric {
  function { TorusX(u, v) } function { 0.3*sin(v) } function { TorusZ(u, v) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { sphere { 0, 1.2 } }
  max_gradient 1.2
  precompute 12 x, y, z
  pigment { rgb <0.5, 0.9, 0.6> } finish { phong 0.5 }
  rotate x*-50 translate <2.5, 0.6, 0.3>
}
