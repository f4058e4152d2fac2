// Hand-written POV-Ray 3.7 twin of sphere-box-shadows.xml (written from
// POV-Ray 3.7's documentation, not exported), so an exporter bug cannot hide a renderer bug.
// Lucent's material k_a, k_d, k_s, n_s maps onto pigment k_d, ambient k_a/k_d (POV-Ray
// multiplies ambient by the pigment), diffuse 1 and specular k_s with roughness 1/n_s
// (POV-Ray's specular is Blinn's half-vector highlight with exponent 1/roughness).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

#macro Plastic(Kd, Ka, Ks, Ns)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end

background { rgb <0.3, 0.4, 0.55> }
// POV-Ray is left-handed: a negative right vector renders our right-handed world as it is;
// angle is the horizontal field of view.
camera {
  perspective
  location <0, 3, 7>
  right -x * 320 / 240
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-4, 7, 5> color rgb 1 }

plane { y, 0 Plastic(<0.7, 0.7, 0.65>, 0.1, 0, 1) }
sphere { <-1.2, 1, 0>, 1 Plastic(<0.8, 0.15, 0.1>, <0.1, 0.02, 0.02>, 0.6, 60) }
box { <0.4, 0, -1>, <2.2, 1.4, 0.6> Plastic(<0.2, 0.4, 0.8>, <0.02, 0.05, 0.1>, 0.3, 20) }
