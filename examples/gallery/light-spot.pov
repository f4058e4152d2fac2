// Hand-written POV-Ray 3.7 twin of light-spot.xml (written from POV-Ray's documentation,
// not exported). Lucent's spot with `angle` A and `inner` I is POV-Ray's spotlight with
// falloff A, radius I and tightness 0: full light inside I, POV-Ray's smoothstep
// (3 - 2u)u^2 between I and A, none beyond. Without `inner` (I = A) the edge is hard.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

#macro Matte(Kd, Ka, Ks, Ns)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end

background { rgb <0.02, 0.02, 0.03> }
camera {
  perspective
  location <0, 4, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.5, 0>
}

light_source {
  <-2, 5, 2> color rgb <1, 0.8, 0.5>
  spotlight point_at <-0.8, 0, 0> radius 20 falloff 20 tightness 0
}
light_source {
  <3, 4, 0> color rgb <0.5, 0.7, 1>
  spotlight point_at <3 - 1, 4 - 1.4, 0> radius 10 falloff 30 tightness 0
}

plane { y, 0 Matte(0.8, 0.03, 0, 1) }
sphere { <0, 0.7, 0>, 0.7 Matte(0.8, 0.03, 0.6, 60) }
