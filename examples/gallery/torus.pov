// Hand-written POV-Ray 3.7 twin of torus.xml (written from POV-Ray's documentation, not
// exported). Both renderers put the torus in the xz-plane around the y axis:
// torus { major, minor }. Lucent's transform list rotate-x(90) rotate-y(20) translate(...)
// applies in the order written, as POV-Ray's rotate / rotate / translate do.
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

background { rgb <0.15, 0.2, 0.25> }
camera {
  perspective
  location <0, 3.2, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-4, 6, 5> color rgb 1 }
light_source { <4, 5, 3> color rgb 0.3 }

plane { y, 0 Plastic(0.65, 0.1, 0, 1) }
torus { 1.1, 0.3
  Plastic(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.8, 80)
  translate <-0.5, 0.3, 0>
}
torus { 1.0, 0.25
  Plastic(<0.2, 0.5, 0.8>, <0.03, 0.06, 0.1>, 0.8, 80)
  rotate x * 90
  rotate y * 20
  translate <0.5, 1.3, 0>
}
