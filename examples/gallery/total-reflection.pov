// Hand-written POV-Ray 3.7 twin of total-reflection.xml (written from POV-Ray's
// documentation, not exported). Lucent's glass without Fresnel (transmissive k_t,
// reflective k_r) is a black pigment with transmit k_t; under total internal reflection
// POV-Ray continues the reflected ray with weight 1, which is Lucent's full-tir="true".
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 8 adc_bailout 0.0039 }

#macro Glass(Kt, Kr)
  texture {
    pigment { rgbt <0, 0, 0, Kt> }
    finish { ambient 0 diffuse 0 specular 0 phong 0 reflection { Kr } }
  }
#end
#macro Checker(C1, C2, S, Ka, Kd)
  texture {
    pigment { checker rgb C1, rgb C2 scale S }
    finish { ambient Ka diffuse Kd specular 0 phong 0 reflection 0 }
  }
#end

background { rgb <0.4, 0.5, 0.6> }
camera {
  perspective
  location <0, 2.2, 6>
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 5> color rgb 1 }

plane { y, 0 Checker(<0.9, 0.85, 0.75>, <0.2, 0.3, 0.5>, 0.5, 0.15, 0.8) }
plane { z, -3 Checker(0.85, 0.35, 0.75, 0.2, 0.7) }
box { -0.7, 0.7 Glass(0.7, 0.1) interior { ior 1.5 } rotate <30, 0, 0> rotate <0, 40, 0> translate <-1.1, 1, 0> }
box { -0.5, 0.5 Glass(0.6, 0.2) interior { ior 1.8 } rotate <0, 0, 45> rotate <0, 20, 0> translate <1.3, 0.75, 0.5> }
