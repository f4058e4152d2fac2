// Hand-written POV-Ray 3.7 twin of cylinders.xml (written from POV-Ray's documentation, not
// exported). Lucent's cylinder (base, cap, radius) is POV-Ray's cylinder { base, cap, r },
// closed by end discs unless open="true", which is `open`.
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

background { rgb <0.2, 0.25, 0.3> }
camera {
  perspective
  location <0, 3.5, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 6> color rgb 1 }
light_source { <4, 3, 2> color rgb 0.4 }

plane { y, 0 Plastic(0.6, 0.1, 0, 1) }
cylinder { <-2, 0, -0.5>, <-2, 1.8, -0.5>, 0.6
  Plastic(<0.85, 0.5, 0.15>, <0.1, 0.06, 0.02>, 0.5, 40) }
cylinder { <-0.6, 0.45, 1>, <0.9, 0.45, 0.2>, 0.45
  Plastic(<0.2, 0.7, 0.25>, <0.03, 0.08, 0.03>, 0.5, 40) }
cylinder { <1.6, 0.2, -1>, <2.4, 1.9, 0.2>, 0.55 open
  Plastic(<0.75, 0.75, 0.8>, 0.1, 0.4, 30) }
