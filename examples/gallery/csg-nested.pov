// Hand-written POV-Ray 3.7 twin of csg-nested.xml (written from POV-Ray's documentation, not
// exported). The CSG tree is the same in both languages; the surface the union of cylinders
// carves out of the intersection shows the union's (green) texture, the remaining faces
// of the box and the sphere their own.
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
#declare Blue = Plastic(<0.15, 0.3, 0.85>, 0.12, 0.4, 60)
#declare Red = Plastic(<0.85, 0.15, 0.12>, 0.12, 0.4, 60)
#declare Green = Plastic(<0.2, 0.7, 0.25>, 0.12, 0.4, 60)

background { rgb <0.1, 0.12, 0.16> }
camera {
  perspective
  location <3.2, 2.6, 4.4>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 40
  look_at <0, 0, 0>
}
light_source { <5, 8, 6> color rgb 1 }
light_source { <-6, 3, 2> color rgb 0.35 }

difference {
  intersection {
    box { <-1, -1, -1>, <1, 1, 1> texture { Red } }
    sphere { <0, 0, 0>, 1.32 texture { Blue } }
  }
  union {
    cylinder { <-1.6, 0, 0>, <1.6, 0, 0>, 0.55 }
    cylinder { <0, -1.6, 0>, <0, 1.6, 0>, 0.55 }
    cylinder { <0, 0, -1.6>, <0, 0, 1.6>, 0.55 }
    texture { Green }
  }
  rotate y * 15
}
