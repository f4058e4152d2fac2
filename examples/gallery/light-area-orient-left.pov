// Hand-written POV-Ray 3.7 twin of light-area-orient-left.xml (written from POV-Ray's
// documentation, not exported), in POV-Ray's own left-handed coordinates: every z of the
// Lucent scene negated and the camera's right +x, as the importer maps a POV-Ray scene.
// Lucent's oriented light with handedness="left" turns its disc as POV-Ray's `orient` does
// here; its samples (4 x 2, no adaptive, no jitter) are POV-Ray's full subdivision.
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
  location <0, 4.5, -8>
  right x * 320 / 240
  up y
  angle 50
  look_at <0, 0.6, 0>
}

light_source {
  <-1, 7, -1.5>
  color rgb <0.55, 0.5, 0.4>
  area_light <2.4, 0, 0>, <0, 0, -2.4>, 4, 4
  circular
}
light_source {
  <7, 1.8, 1>
  color rgb <0.6, 0.7, 1>
  area_light <3, 0, 0>, <0, 0, -3>, 4, 2
  circular
  orient
}

plane { y, 0 Surface(0.8, 1, 0, 1) }
sphere { <-1.2, 0.8, 0>, 0.8 Surface(<0.85, 0.35, 0.2>, <1, 0.4, 0.25>, 0.4, 50) }
cylinder { <1.2, 0, -0.6>, <1.2, 1.8, -0.6>, 0.15 Surface(0.7, 0.9, 0, 1) }
box { <0.3, 0, 0.8>, <1.1, 0.8, 1.6> Surface(<0.25, 0.5, 0.85>, <0.3, 0.5, 1>, 0.3, 40) }
cylinder { <-0.3, 0, -1.9>, <-0.3, 0.9, -1.9>, 0.1 Surface(<0.8, 0.8, 0.3>, <1, 1, 0.4>, 0, 1) }
