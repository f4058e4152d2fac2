// Hand-written POV-Ray 3.7 twin of bicubic-patch.xml (written from POV-Ray's documentation,
// not exported). Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 2.5, 6>
  right -x*4/3
  up y
  angle 50
  look_at <0, 0.4, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
light_source { <3, 2, 5> color rgb 0.5 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

// A sheet bent at its corners (POV-Ray's bezier.pov sample), cut into 8 x 8 parts.
bicubic_patch {
  type 1 flatness 0 u_steps 3 v_steps 3
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
  translate <-1.5, -1.5, 0> scale 0.6 rotate -60*x rotate 20*y translate <-1.3, 0.4, 0>
}
// A saddle, cut where it is not flat to 0.02 (at most 16 x 4 parts). Its own transforms
// are a rotation and a translation: POV-Ray's flatness, decided after them, is the same.
bicubic_patch {
  type 0 flatness 0.02 u_steps 4 v_steps 2
  <-1, 0.8, -1>, <-1, 0, -0.33>, <-1, 0, 0.33>, <-1, -0.8, 1>,
  <-0.33, 0, -1>, <-0.33, 0, -0.33>, <-0.33, 0, 0.33>, <-0.33, 0, 1>,
  <0.33, 0, -1>, <0.33, 0, -0.33>, <0.33, 0, 0.33>, <0.33, 0, 1>,
  <1, -0.8, -1>, <1, 0, -0.33>, <1, 0, 0.33>, <1, 0.8, 1>
  Surface(<0.2, 0.35, 0.8>, <0.02, 0.04, 0.1>, 0.4, 40)
  rotate 30*y translate <1.3, 0.3, 0>
}
