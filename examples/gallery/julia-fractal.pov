// Hand-written POV-Ray 3.7 twin of julia-fractal.xml (written from POV-Ray's documentation,
// not exported). Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 1.8, 8>
  right -x*4/3
  up y
  angle 45
  look_at <0, 0.1, 0>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <4, 3, 6> color rgb 0.4 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

// Quaternion z² + c.
julia_fractal {
  <-0.083, 0, -0.83, -0.025>
  quaternion sqr
  max_iteration 8
  precision 20
  Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
  rotate 30*y translate <-2.5, 0.2, 0>
}
// Quaternion z³ + c, sliced by a tilted 3-D space.
julia_fractal {
  <-0.03, 0.5, -0.2, -0.5>
  quaternion cube
  max_iteration 8
  precision 20
  slice <0.2, 0, 0.3, 1>, 0.1
  Surface(<0.25, 0.5, 0.85>, <0.02, 0.05, 0.1>, 0.5, 40)
  scale 1.1 rotate -20*x translate <0, 0.3, 0>
}
// Hypercomplex z² + c.
julia_fractal {
  <-0.745, 0, 0.113, 0.05>
  hypercomplex sqr
  max_iteration 9
  precision 20
  Surface(<0.8, 0.6, 0.8>, <0.08, 0.06, 0.08>, 0.6, 80)
  scale <0.8, 1.2, 0.8> rotate 135*x rotate -30*y translate <2.6, 0.3, 0>
}
plane {
  y, -1.2
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}
