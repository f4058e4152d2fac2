// Hand-written POV-Ray 3.7 twin of csg-coincident.xml (written from POV-Ray's documentation,
// not exported). Where CSG operands' surfaces coincide POV-Ray decides pixel by pixel by
// rounding (it lids the flush pocket and speckles the spheres), so this twin does what a
// POV-Ray user does to get the image Lucent's rule gives: the pocket's box reaches a little
// above the block's top, and the second sphere is a little smaller than the first.
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
#declare Red = Plastic(<0.85, 0.15, 0.12>, 0.12, 0.4, 60)
#declare Green = Plastic(<0.2, 0.7, 0.25>, 0.12, 0.4, 60)
#declare Blue = Plastic(<0.15, 0.3, 0.85>, 0.12, 0.4, 60)

background { rgb <0.1, 0.12, 0.16> }
camera {
  perspective
  location <0.2, 3.8, 4.6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 48
  look_at <0.2, -0.1, 0>
}
light_source { <4, 8, 6> color rgb 1 }
light_source { <-6, 3, 2> color rgb 0.35 }

difference {
  box { <-1, -1, -1>, <1, 0.5, 1> texture { Red } }
  box { <-0.55, -0.4, -0.55>, <0.55, 0.501, 0.55> texture { Green } }
  rotate y * 20
  translate <-1, 0, 0>
}
union {
  sphere { <1.4, 0, 0.2>, 0.8 texture { Red } }
  sphere { <1.4, 0, 0.2>, 0.799 texture { Blue } }
}
