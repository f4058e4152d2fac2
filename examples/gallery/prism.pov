// Hand-written POV-Ray 3.7 twin of prism.xml (written from POV-Ray's documentation, not
// exported). A prism's points are x z pairs swept along y from height1 to height2, as
// Lucent's <prism>. Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment
// k_d, ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.4, 7.2>
  right -x*4/3
  up y
  angle 48
  look_at <0, 0.5, 0>
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

// A five-pointed star (each polygon closed by repeating its first point) with a
// pentagonal hole: the second polygon.
prism {
  linear_sweep linear_spline 0, 0.4, 17
  <0, 1>, <-0.2645, 0.3641>, <-0.9511, 0.309>, <-0.428, -0.1391>, <-0.5878, -0.809>,
  <0, -0.45>, <0.5878, -0.809>, <0.428, -0.1391>, <0.9511, 0.309>, <0.2645, 0.3641>, <0, 1>,
  <-0.1293, 0.178>, <-0.2092, -0.068>, <0, -0.22>, <0.2092, -0.068>, <0.1293, 0.178>, <-0.1293, 0.178>
  texture { Gold }
  scale 1.2 rotate y*10 translate <-2, 0, -0.6>
}

// A heart of two cubic Bézier segments (four points each).
prism {
  bezier_spline 0, 0.5, 8
  <0, -1>, <1.3, -0.2>, <0.9, 1.1>, <0, 0.6>,
  <0, 0.6>, <-0.9, 1.1>, <-1.3, -0.2>, <0, -1>
  texture { Red }
  scale 0.9 rotate y*180 translate <0.3, 0, -1.4>
}

// A conic sweep: the square is the section at y = 1, shrinking towards the origin; from
// 0.5 to 1 it is a frustum, turned over so that it narrows upwards.
prism {
  conic_sweep linear_spline 0.5, 1, 5
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  texture { Green }
  rotate x*180 scale 0.8 rotate y*20 translate <2, 0.8, -0.4>
}

// A block minus an oval cubic-spline prism (a control point before the first point and
// one after the closing point); the cut faces keep the oval's colour.
difference {
  prism { 0, 0.8, 5 <-0.6, -0.5>, <0.6, -0.5>, <0.6, 0.5>, <-0.6, 0.5>, <-0.6, -0.5> texture { Blue } }
  prism {
    cubic_spline -0.1, 0.9, 9
    <0.2, -0.2771>, <0.4, 0>, <0.2, 0.2771>, <-0.2, 0.2771>, <-0.4, 0>, <-0.2, -0.2771>,
    <0.2, -0.2771>, <0.4, 0>, <0.2, 0.2771>
    texture { Red }
    translate <0.15, 0, 0>
  }
  rotate y*-25
  translate <-0.5, 0, 1.1>
}
