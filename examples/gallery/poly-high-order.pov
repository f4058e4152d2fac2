// Hand-written POV-Ray 3.7 twin of poly-high-order.xml (written from POV-Ray's documentation
// and shapesq.inc, not exported). Lucent's material (k_a, k_d, specular k_s with shininess s)
// is pigment k_d, ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right
// vector is negated to keep Lucent's right-handed axes, so the coefficients are the XML's.
// Orders above 4 are always solved with Sturm sequences by POV-Ray; `sturm` is written anyway.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 4.6, 9.2>
  right -x*4/3
  up y
  angle 45
  look_at <0, 0.75, 0>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <4, 3, 6> color rgb 0.4 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

// Twin_Glob (shapesq.inc): 4x^6 - 4x^4 + y^2 + z^2.
poly {
  6,
  <4, 0, 0, 0, 0, 0, 0, 0, 0, -4, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0>
  sturm
  Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
  rotate 90*z translate <-2.7, 1.05, 0>
}
// Glob_5 (shapesq.inc): -0.5x^5 - 0.5x^4 + y^2 + z^2, its teardrop cut out by a box.
intersection {
  poly {
    5,
    <-0.5, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0>
    sturm
  }
  box { <-1.05, -0.4, -0.4>, <0, 0.4, 0.4> }
  Surface(<0.25, 0.5, 0.85>, <0.02, 0.05, 0.1>, 0.5, 40)
  rotate 90*z scale 2.5 translate <-0.95, 2.55, 0>
}
// Three balls joined: the product of their spheres less 0.012.
poly {
  6,
  <1, 0, 0, 0, 3, 0, -1.7, 3, 0, -0.585, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 3, 0, -3.4, 6, 0, 0.04, 0, -3.4,
     0, 1.8785, 3, 0, 0.04, 0, -0.57184375, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     1, 0, -1.7, 3, 0, 0.625, 0, -3.4, 0, -0.1785, 3, 0, 1.25, 0,
     0.05735625, 0, -1.7, 0, -0.1785, 0, -0.004685625, 1, 0, 0.625, 0, 0.05735625, 0, -0.01056675>
  sturm
  Surface(<0.8, 0.6, 0.8>, <0.08, 0.06, 0.08>, 0.6, 80)
  translate <0.85, 0.52, 0.3>
}
// x^8 + y^8 + z^8 - 1.
poly {
  8,
  <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 1, 0, 0, 0, 0, 0, 0, 0, -1>
  sturm
  Surface(<0.3, 0.7, 0.4>, <0.03, 0.08, 0.04>, 0.5, 50)
  scale 0.62 rotate 30*y translate <2.75, 0.62, 0>
}
plane {
  y, 0
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}
