// POV-Ray 3.7 twin of torus_small.xml, written by hand (docs/accuracy.md).
// povray +Iexamples/accuracy/torus_small.pov +Otorus_small_pov.png +W320 +H240 -D -V -GS -GR
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
background { rgb <0.1, 0.12, 0.16> }
camera { location <0, 0, 5e-4> right -x*4/3 up y angle 40 look_at <0, 0, 0> }
light_source { <2e-4, 6e-4, 6e-4> color rgb 1 }
torus { 1e-4, 2.5e-5
  texture { pigment { rgb <0.8, 0.45, 0.2> }
    finish { ambient rgb <0.1/0.8, 0.1/0.45, 0.1/0.2> diffuse 1 specular 0.6 roughness 1/80 } }
  rotate x*20 }
