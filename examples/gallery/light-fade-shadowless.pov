// Hand-written POV-Ray 3.7 twin of light-fade-shadowless.xml (written from POV-Ray's
// documentation, not exported). Lucent's fade-distance and fade-power are POV-Ray's
// fade_distance and fade_power; a light with shadows="false" highlights="false" is POV-Ray's
// shadowless light, which gives neither shadows nor highlights.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.02, 0.02, 0.03> }
camera {
  perspective
  location <0, 3, 6>
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.4, 0>
}

light_source { <0.3, 1.2, 0.6> color rgb <0.45, 0.4, 0.3> fade_distance 1.5 fade_power 3 }
light_source { <-6, 3, 2> color rgb <0.35, 0.45, 0.6> shadowless }
light_source { <3, 6, 5> color rgb 0.4 }

plane { y, 0 texture { pigment { rgb 0.8 } finish { ambient 0.03 / 0.8 diffuse 1 } } }
sphere {
  <-1.2, 0.5, 0>, 0.5
  texture {
    pigment { rgb <0.7, 0.25, 0.2> }
    finish { ambient rgb 0.03 / <0.7, 0.25, 0.2> diffuse 1 phong 0.8 phong_size 40 }
  }
}
sphere {
  <1.3, 0.5, -0.3>, 0.5
  texture {
    pigment { rgb <0.2, 0.4, 0.8> }
    finish { ambient rgb 0.03 / <0.2, 0.4, 0.8> diffuse 1 specular 0.7 roughness 1 / 50 }
  }
}
