// POV-Ray 3.7 twin of torus_edge_on.xml, written by hand (docs/accuracy.md).
// povray +Iexamples/accuracy/torus_edge_on.pov +Otorus_edge_on_pov.png +W320 +H240 -D -V -GS -GR
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
background { rgb <0.1, 0.12, 0.16> }
// Lucent's world is right-handed: right -x keeps the coordinates.
camera { location <0, 0, 5> right -x*4/3 up y angle 40 look_at <0, 0, 0> }
light_source { <2, 6, 6> color rgb 1 }
// Lucent material → POV-Ray finish: ambient k_a/k_d per channel, roughness 1/shininess.
#declare Copper = texture { pigment { rgb <0.8, 0.45, 0.2> }
  finish { ambient rgb <0.1/0.8, 0.1/0.45, 0.1/0.2> diffuse 1 specular 0.6 roughness 1/80 } }
#declare Steel = texture { pigment { rgb <0.35, 0.5, 0.8> }
  finish { ambient rgb <0.1/0.35, 0.1/0.5, 0.1/0.8> diffuse 1 specular 0.6 roughness 1/80 } }
torus { 1.2, 0.3 texture { Copper } }
torus { 1.3, 0.026 texture { Steel } rotate x*3 translate <0, 0.55, 0> }
plane { y, -0.75
  texture { pigment { checker rgb 0.6, rgb 0.3 scale 0.5 } finish { ambient 0.1 diffuse 1 } } }
