// POV-Ray 3.7 twin of sphere_far.xml, written by hand (docs/accuracy.md).
// povray +Iexamples/accuracy/sphere_far.pov +Osphere_far_pov.png +W320 +H240 -D -V -GS -GR
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
background { rgb <0.1, 0.12, 0.16> }
camera { location <100000.6, 0.9, 4> right -x*4/3 up y angle 45 look_at <100000, 0, 0> }
light_source { <100003, 6, 5> color rgb 1 }
sphere { <100000, 0, 0>, 1
  texture { pigment { rgb <0.2, 0.25, 0.3> }
    finish { ambient rgb <0.05/0.2, 0.05/0.25, 0.05/0.3> diffuse 1 specular 0.8 roughness 1/120
             reflection { 0.6 } } } }
sphere { <100001.6, -0.6, 0.9>, 0.4
  texture { pigment { rgb <0.85, 0.2, 0.15> }
    finish { ambient rgb <0.1/0.85, 0.1/0.2, 0.1/0.15> diffuse 1 specular 0.5 roughness 1/60 } } }
plane { y, -1
  texture { pigment { checker rgb 0.7, rgb 0.25 scale 0.4 } finish { ambient 0.1 diffuse 1 } } }
