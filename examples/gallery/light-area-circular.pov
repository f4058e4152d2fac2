// Hand-written POV-Ray 3.7 twin of light-area-circular.xml (written from POV-Ray's
// documentation, not exported). Lucent's circular area light is POV-Ray's `circular`, its
// oriented one `circular orient` (the axes of equal length, as orient asks). With adaptive
// 2 POV-Ray's subdivision is Lucent's adaptive="2"; the 8 x 8 light without adaptive has
// POV-Ray's full subdivision, whose weights on 8 samples a side are Lucent's plain average.
// No jitter: POV-Ray's is random.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.05 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, k_a and a specular highlight of the given shininess: pigment k_d, ambient
// k_a / k_d (POV-Ray scales ambient by the pigment), diffuse 1.
#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

background { rgb <0.02, 0.02, 0.03> }
camera {
  perspective
  location <0, 4.5, 8>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.6, 0>
}

light_source {
  <-1, 7, 1.5>
  color rgb <0.85, 0.75, 0.6>
  area_light <2.4, 0, 0>, <0, 0, 2.4>, 9, 9
  adaptive 2
  circular
}
light_source {
  <7, 1.8, -1>
  color rgb <0.5, 0.6, 0.9>
  area_light <2, 0, 0>, <0, 0, 2>, 8, 8
  circular
  orient
}

plane { y, 0 Surface(0.8, 1, 0, 1) }
sphere { <-1.2, 0.8, 0>, 0.8 Surface(<0.85, 0.35, 0.2>, <1, 0.4, 0.25>, 0.4, 50) }
cylinder { <1.2, 0, 0.6>, <1.2, 1.8, 0.6>, 0.15 Surface(0.7, 0.9, 0, 1) }
box { <0.3, 0, -1.6>, <1.1, 0.8, -0.8> Surface(<0.25, 0.5, 0.85>, <0.3, 0.5, 1>, 0.3, 40) rotate y * 30 }
cylinder { <-0.3, 0, 1.9>, <-0.3, 0.9, 1.9>, 0.1 Surface(<0.8, 0.8, 0.3>, <1, 1, 0.4>, 0, 1) }
