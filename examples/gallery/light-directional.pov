// Hand-written POV-Ray 3.7 twin of light-directional.xml (written from
// POV-Ray's documentation, not exported). A Lucent directional light travelling along d is
// POV-Ray's parallel light: placed far up the other way (-d) and pointing at the origin,
// so that L = -d everywhere and every object of the scene lies in front of it.
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
#declare Post = Plastic(<0.8, 0.7, 0.5>, <0.08, 0.07, 0.05>, 0.3, 30)

background { rgb <0.5, 0.65, 0.85> }
camera {
  perspective
  location <0, 5, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 55
  look_at <0, 0.3, 0>
}
light_source { <1, 0.6, 0.4> * 10000 color rgb <1, 0.9, 0.75> parallel point_at <0, 0, 0> }
// Colour times intensity: <0.3, 0.35, 0.5> * 0.6.
light_source { <-0.6, 1, -0.3> * 10000 color rgb <0.18, 0.21, 0.3> parallel point_at <0, 0, 0> }

plane { y, 0 Plastic(<0.7, 0.75, 0.65>, 0.1, 0, 1) }
box { <-2.15, 0, -1.15>, <-1.85, 1.5, -0.85> texture { Post } }
box { <-0.15, 0, -1.15>, <0.15, 1.5, -0.85> texture { Post } }
box { <1.85, 0, -1.15>, <2.15, 1.5, -0.85> texture { Post } }
box { <-2.15, 0, 0.85>, <-1.85, 1, 1.15> texture { Post } }
box { <-0.15, 0, 0.85>, <0.15, 1, 1.15> texture { Post } }
box { <1.85, 0, 0.85>, <2.15, 1, 1.15> texture { Post } }
sphere { <0, 0.5, 0>, 0.5 Plastic(<0.2, 0.45, 0.8>, <0.02, 0.05, 0.1>, 0.6, 80) }
