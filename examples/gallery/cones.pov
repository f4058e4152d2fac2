// Hand-written POV-Ray 3.7 twin of cones.xml (written from POV-Ray's documentation, not
// exported). Lucent's cone (base, base-radius, cap, cap-radius) is POV-Ray's
// cone { base, r_base, cap, r_cap }; a missing cap-radius is 0 (a point), and
// open="true" is `open` (no end discs).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, k_a, k_s, n_s: pigment k_d, ambient k_a / k_d (POV-Ray scales ambient by the
// pigment), diffuse 1, Blinn specular k_s with roughness 1 / n_s.
#macro Plastic(Kd, Ka, Ks, Ns)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end

background { rgb <0.25, 0.2, 0.3> }
camera {
  perspective
  location <0, 3.5, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 6> color rgb 1 }
light_source { <4, 4, 3> color rgb 0.35 }

plane { y, 0 Plastic(<0.6, 0.62, 0.6>, 0.1, 0, 1) }
cone { <-2, 0, -0.5>, 0.8, <-2, 2, -0.5>, 0
  Plastic(<0.8, 0.25, 0.2>, <0.1, 0.03, 0.03>, 0.5, 50) }
cone { <0, 0, 0.5>, 0.8, <0, 1.1, 0.5>, 0.4
  Plastic(<0.25, 0.45, 0.85>, <0.03, 0.05, 0.1>, 0.5, 50) }
cone { <2, 0.3, -0.6>, 0.35, <2.2, 1.6, 0.4>, 0.75 open
  Plastic(<0.85, 0.8, 0.3>, <0.1, 0.1, 0.03>, 0.4, 30) }
