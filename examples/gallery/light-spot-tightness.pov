// Hand-written POV-Ray 3.7 twin of light-spot-tightness.xml (written from POV-Ray's
// documentation, not exported). Lucent's spot with angle A, inner I and tightness T is
// POV-Ray's spotlight with falloff A, radius I and tightness T; its cylindrical light with
// radius, falloff and tightness is POV-Ray's cylinder light with the same three.
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
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.5, 0>
}

light_source {
  <-1.5, 5, 1> color rgb <1, 0.85, 0.6>
  spotlight point_at <-1, 0, 0> radius 45 falloff 60 tightness 25
}
light_source {
  <2, 5, 0> color rgb <0.5, 0.7, 1>
  cylinder point_at <1.8, 0, 0> radius 0.6 falloff 1.4 tightness 3
}

plane { y, 0 Matte(0.8, 0.03, 0, 1) }
sphere { <0, 0.7, 0>, 0.7 Matte(0.8, 0.03, 0.6, 60) }
