// POV-Ray 3.7 twin of scaled_1e-4.xml, written by hand (docs/accuracy.md). Declare S=1 to
// render the unit-scale scene: povray ... Declare=S=1
// povray +Iexamples/accuracy/scaled_1e-4.pov +Oscaled_1e-4_pov.png +W320 +H240 -D -V -GS -GR
#version 3.7;
#ifndef (S) #declare S = 1e-4; #end
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
background { rgb <0.1, 0.12, 0.16> }
camera { location <0, 2.2, 6>*S right -x*4/3 up y angle 40 look_at <0, 0.6, 0>*S }
light_source { <3, 6, 5>*S color rgb 1 }
#declare Mirror = texture { pigment { rgb <0.2, 0.25, 0.3> }
  finish { ambient rgb <0.05/0.2, 0.05/0.25, 0.05/0.3> diffuse 1 specular 0.8 roughness 1/120
           reflection { 0.6 } } }
#declare Blue = texture { pigment { rgb <0.2, 0.35, 0.85> }
  finish { ambient rgb <0.1/0.2, 0.1/0.35, 0.1/0.85> diffuse 1 specular 0.5 roughness 1/60 } }
#declare Copper = texture { pigment { rgb <0.8, 0.45, 0.2> }
  finish { ambient rgb <0.1/0.8, 0.1/0.45, 0.1/0.2> diffuse 1 specular 0.6 roughness 1/80 } }
#declare Green = texture { pigment { rgb <0.25, 0.7, 0.3> }
  finish { ambient rgb <0.1/0.25, 0.1/0.7, 0.1/0.3> diffuse 1 specular 0.5 roughness 1/60 } }
union {
  plane { y, 0.25
    texture { pigment { checker rgb 0.7, rgb 0.25 scale 0.5 } finish { ambient 0.1 diffuse 1 } }
    translate -0.25*y }
  sphere { <-1.1, 0.7, 0>, 0.7 texture { Mirror } }
  box { <-0.45, 0, -0.45>, <0.45, 0.9, 0.45> texture { Blue } rotate y*30 translate <0.5, 0, -1.2> }
  torus { 0.5, 0.16 texture { Copper } rotate x*90 translate <0.6, 0.66, 0.6> }
  cone { <1.7, 0, -0.3>, 0.45, <1.7, 1.2, -0.3>, 0 texture { Green } }
  scale S
}
