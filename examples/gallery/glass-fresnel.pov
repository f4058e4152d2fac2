// Hand-written POV-Ray 3.7 twin of glass-fresnel.xml (written from POV-Ray's documentation,
// not exported). Lucent's fresnel glass (transmissive 1, reflective 1, fresnel) reflects
// F and transmits 1 - F: POV-Ray's `reflection { 0, 1 fresnel on }` gives F and
// conserve_energy scales the transmitted light by 1 - F. The pigment is fully transmitting
// (rgbt 1), so no local term but the highlight (coloured by the light only) remains.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 8 adc_bailout 0.0039 }

#declare Glass = texture {
  pigment { rgbt 1 }
  finish {
    ambient 0 diffuse 0 phong 0
    specular 1 roughness 1 / 300
    reflection { 0, 1 fresnel on }
    conserve_energy
  }
}
// A checker pigment with Lucent's colours, ambient k_a and diffuse k_d (ambient is scaled
// by the pigment in both renderers when k_a is one number).
#macro Checker(C1, C2, Size, Ka, Kd)
  texture {
    pigment { checker rgb C1, rgb C2 scale Size }
    finish { ambient Ka diffuse Kd specular 0 phong 0 reflection 0 }
  }
#end

background { rgb <0.5, 0.6, 0.7> }
camera {
  perspective
  location <0, 2.2, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 5> color rgb 1 }

plane { y, 0 Checker(0.9, 0.25, 0.5, 0.15, 0.8) }
// Lucent's plane normal 0 0 1, offset -3 (the half-space z < -3 is inside).
plane { z, -3 Checker(<0.9, 0.6, 0.3>, <0.2, 0.3, 0.6>, 0.6, 0.2, 0.7) }
sphere { <-1.3, 1, 0>, 1 texture { Glass } interior { ior 1.5 } }
sphere { <1.4, 0.6, 0.8>, 0.6 texture { Glass } interior { ior 2.4 } }
box { <0.3, 0, -1.6>, <2.3, 1.4, -1.2> texture { Glass } interior { ior 1.5 } }
