// Hand-written POV-Ray 3.7 twin of fade-on-exit.xml (written from POV-Ray's documentation,
// not exported): glass-fresnel.pov's glass with an interior fade. POV-Ray dims by the fade
// only the light that passes out of the glass (and what total internal reflection keeps
// inside), which Lucent's fade-on-exit="true" selects.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 10 adc_bailout 0.0039 }

#declare Glass = texture {
  pigment { rgbt 1 }
  finish {
    ambient 0 diffuse 0 phong 0
    specular 1 roughness 1 / 300
    reflection { 0, 1 fresnel on }
    conserve_energy
  }
}
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
plane { z, -3 Checker(<0.9, 0.6, 0.3>, <0.2, 0.3, 0.6>, 0.6, 0.2, 0.7) }
sphere { <-1.3, 1, 0>, 1 texture { Glass }
  interior { ior 1.5 fade_distance 0.6 fade_power 2 fade_color rgb <0.9, 0.5, 0.1> } }
sphere { <1.4, 0.6, 0.8>, 0.6 texture { Glass }
  interior { ior 2.4 fade_distance 0.4 fade_power 1 fade_color rgb <0.2, 0.4, 0.9> } }
box { <0.3, 0, -1.6>, <2.3, 1.4, -1.2> texture { Glass }
  interior { ior 1.5 fade_distance 0.3 fade_power 2 fade_color rgb <0.3, 0.8, 0.4> } }
