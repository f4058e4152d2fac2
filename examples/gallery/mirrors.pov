// Hand-written POV-Ray 3.7 twin of mirrors.xml (written from POV-Ray's documentation, not
// exported). Lucent's reflective k_r is POV-Ray's constant `reflection rgb k_r`, which
// neither renderer multiplies by the pigment; both cut the recursion at depth 5 with black.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, k_a, k_s, n_s, k_r: pigment k_d, ambient k_a / k_d (POV-Ray scales ambient
// by the pigment), diffuse 1, Blinn specular k_s with roughness 1 / n_s, reflection k_r.
#macro Mirror(Kd, Ka, Ks, Ns, Kr)
  texture {
    pigment { rgb Kd }
    finish {
      ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0
      reflection { rgb Kr }
    }
  }
#end

background { rgb <0.35, 0.45, 0.6> }
camera {
  perspective
  location <0, 2.5, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 55
  look_at <0, 1, 0>
}
light_source { <-3, 6, 6> color rgb 1 }

// The checker colour T multiplies k_d and, ambient being one number, k_a too.
plane { y, 0
  texture {
    pigment { checker rgb 0.9, rgb 0.2 }
    finish { ambient 0.1 diffuse 0.8 specular 0 phong 0 reflection 0 }
  }
}
box { <-3, 0, -2.3>, <3, 2.8, -2> Mirror(0.05, 0.02, 0.5, 200, <0.7, 0.75, 0.8>) }
sphere { <-1.1, 0.9, -0.3>, 0.9 Mirror(0.05, 0, 1, 300, 0.9) }
sphere { <1.1, 0.7, 0.6>, 0.7
  Mirror(<0.2, 0.1, 0.05>, <0.05, 0.02, 0.01>, 0.8, 150, <0.8, 0.55, 0.3>) }
