// Hand-written POV-Ray 3.7 twin of sphere-sweep.xml (written from POV-Ray's documentation,
// not exported). Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 2.4, 10>
  right -x*4/3
  up y
  angle 45
  look_at <0, 0.3, 0>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <4, 3, 6> color rgb 0.4 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

// Balls joined by tangent cones, the last of radius 0: a point.
sphere_sweep {
  linear_spline 5,
  <-0.6, -1, 0.3>, 0.45, <0.3, -0.2, -0.2>, 0.3, <-0.4, 0.5, 0.2>, 0.35, <0.2, 1.2, 0>, 0.15,
  <0.7, 1.6, 0.4>, 0
  Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
  rotate 20*y translate <-2.7, 0, 0>
}
// Catmull-Rom through the second to the sixth sphere.
sphere_sweep {
  cubic_spline 7,
  <-1.2, -1.6, 0>, 0.05, <-0.9, -0.9, 0.3>, 0.12, <0.3, -0.6, -0.4>, 0.25, <-0.5, 0.3, 0.2>, 0.4,
  <0.4, 0.9, -0.3>, 0.2, <-0.2, 1.5, 0.3>, 0.1, <0.6, 2.2, 0>, 0.05
  Surface(<0.25, 0.5, 0.85>, <0.02, 0.05, 0.1>, 0.5, 40)
  translate <0, 0.1, 0>
}
// A B-spline loop: the spheres repeat, so the path closes.
sphere_sweep {
  b_spline 7,
  <1, 0, 0>, 0.2, <0, 1, 0>, 0.35, <-1, 0, 0>, 0.2, <0, -1, 0>, 0.35, <1, 0, 0>, 0.2,
  <0, 1, 0>, 0.35, <-1, 0, 0>, 0.2
  Surface(<0.8, 0.6, 0.8>, <0.08, 0.06, 0.08>, 0.6, 80)
  scale 0.9 rotate -25*x rotate -20*y translate <2.7, 0.4, 0>
}
plane {
  y, -1.2
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}
