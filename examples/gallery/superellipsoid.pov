// Hand-written POV-Ray 3.7 twin of superellipsoid.xml (written from POV-Ray's documentation,
// not exported). POV-Ray's superellipsoid { <e, n> } has its poles on the z axis, as
// Lucent's <superellipsoid>, so the shapes turned upright are rotated x*-90 in both. Lucent's
// material (k_a, k_d, specular k_s with shininess s) is pigment k_d, ambient k_a / k_d,
// diffuse 1, specular k_s with roughness 1/s; the right vector is negated to keep Lucent's
// right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.4, 7.2>
  right -x*4/3
  up y
  angle 48
  look_at <0, 0.7, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
light_source { <5, 4, 4> color rgb 0.35 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end
#declare Gold = Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
#declare Blue = Surface(<0.2, 0.45, 0.85>, <0.03, 0.06, 0.1>, 0.7, 60)
#declare Red = Surface(<0.85, 0.2, 0.15>, <0.1, 0.03, 0.03>, 0.7, 60)
#declare Green = Surface(<0.2, 0.7, 0.3>, <0.03, 0.1, 0.04>, 0.7, 60)

plane { y, 0 texture { pigment { rgb 0.6 } finish { ambient 0.1 / 0.6 diffuse 1 specular 0 } } }

// A rounded cube, a square-sectioned pillow standing upright, a sphere, an octahedron and
// a pinched star.
superellipsoid { <0.2, 0.2> texture { Gold } scale 0.6 rotate y*25 translate <-2.3, 0.6, -0.8> }
superellipsoid { <0.3, 1> texture { Blue } scale <0.55, 0.55, 0.8> rotate x*-90 rotate y*-20 translate <-0.8, 0.8, -1.4> }
superellipsoid { <1, 1> texture { Red } scale 0.55 translate <0.6, 0.55, -1.5> }
superellipsoid { <2, 2> texture { Green } scale 0.7 rotate x*-90 rotate y*30 translate <2.1, 0.7, -0.9> }
superellipsoid { <2.6, 2.6> texture { Gold } scale 0.75 rotate x*-90 rotate y*15 translate <0.9, 0.75, 0.9> }

// A rounded cube hollowed by a round-edged disc; the cut faces keep the disc's colour.
difference {
  superellipsoid { <0.25, 0.25> texture { Blue } scale 0.55 }
  superellipsoid { <1, 0.3> texture { Red } scale <0.4, 0.4, 0.8> translate <0, 0.25, 0.1> }
  rotate y*-30
  translate <-1.0, 0.55, 1.0>
}
