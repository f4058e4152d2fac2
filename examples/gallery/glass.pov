// Hand-written POV-Ray 3.7 twin of glass.xml (written from POV-Ray's documentation, not
// exported). Lucent's glass without Fresnel (transmissive k_t, reflective k_r, no diffuse or
// ambient) is a black pigment with transmit k_t: POV-Ray scales the local terms by the
// opacity 1 - k_t (they are 0 here) but not the highlight, transmits k_t through every
// surface (shadow rays too) and reflects k_r. Total internal reflection, where POV-Ray and
// Lucent weigh the mirror ray differently, cannot occur in a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 8 adc_bailout 0.0039 }

#macro Glass(Kt, Kr, Ks, Ns)
  texture {
    pigment { rgbt <0, 0, 0, Kt> }
    finish { ambient 0 diffuse 0 specular Ks roughness 1 / Ns phong 0 reflection { Kr } }
  }
#end
// The checker colour T multiplies k_d and, ambient being one number, k_a too.
#macro Checker(C1, C2, S, Ka, Kd)
  texture {
    pigment { checker rgb C1, rgb C2 scale S }
    finish { ambient Ka diffuse Kd specular 0 phong 0 reflection 0 }
  }
#end

background { rgb <0.4, 0.5, 0.6> }
camera {
  perspective
  location <0, 2.5, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 5> color rgb 1 }

plane { y, 0 Checker(<0.9, 0.85, 0.75>, <0.2, 0.3, 0.5>, 0.5, 0.15, 0.8) }
// Lucent's plane normal 0 0 1, offset -3 (the half-space z < -3 is inside).
plane { z, -3 Checker(0.85, 0.35, 0.75, 0.2, 0.7) }
sphere { <-1.1, 1, 0>, 1 Glass(0.9, 0.1, 1, 300) interior { ior 1.5 } }
sphere { <1.3, 0.7, 0.5>, 0.7 Glass(0.85, 0.15, 0.8, 200) interior { ior 1.33 } }
