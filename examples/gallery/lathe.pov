// Hand-written POV-Ray 3.7 twin of lathe.xml (written from POV-Ray's documentation, not
// exported). lathe { SPLINE n, <x, y>... } turns the curve about the y axis, as Lucent's
// <lathe>. Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 2.6, 6.4>
  right -x*4/3
  up y
  angle 44
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

// A bottle: the cubic curve runs from the second point to the last but one, both on the axis.
lathe {
  cubic_spline 9,
  <0, -0.1>, <0, 0>, <0.5, 0.05>, <0.6, 0.45>, <0.3, 0.95>, <0.22, 1.25>, <0.35, 1.45>, <0, 1.5>, <0, 1.6>
  sturm
  texture { Blue }
  translate <-2, 0, -0.6>
}
// A chess pawn from a polygon.
lathe {
  linear_spline 9,
  <0, 0>, <0.6, 0>, <0.6, 0.1>, <0.45, 0.2>, <0.3, 0.35>, <0.18, 0.9>, <0.38, 0.95>, <0.2, 1.05>, <0, 1.05>
  texture { Gold }
  translate <-0.4, 0, -1>
}
// A bowl from three Bezier pieces: the outside, the rim, the inside.
lathe {
  bezier_spline 12,
  <0, 0>, <0.9, 0>, <1.0, 0.3>, <0.9, 0.6>,
  <0.9, 0.6>, <0.8, 0.62>, <0.75, 0.55>, <0.7, 0.25>,
  <0.7, 0.25>, <0.5, 0.15>, <0.3, 0.2>, <0, 0.2>
  sturm
  texture { Green }
  translate <1.6, 0, -0.8>
}
// A spool with a ball cut out of its side; the cut keeps the ball's colour.
difference {
  lathe {
    linear_spline 8,
    <0, 0>, <0.6, 0>, <0.6, 0.15>, <0.3, 0.25>, <0.3, 0.75>, <0.6, 0.85>, <0.6, 1>, <0, 1>
    texture { Red }
  }
  sphere { <0.35, 0.6, 0.3>, 0.35 texture { Gold } }
  rotate y*-30
  translate <0.2, 0, 1.1>
}
