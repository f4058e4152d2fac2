// Hand-written POV-Ray 3.7 twin of moving_sphere.xml: the sphere follows POV-Ray's clock,
// which `lucent compare --frame N` sets (+K) to the clock of frame N.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.3, 0.4, 0.55> }
// POV-Ray is left-handed: a negative right vector renders the right-handed scene as it is.
camera {
  perspective
  location <0, 3, 7>
  right -x * 160 / 120
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-4, 7, 5> color rgb 1 }
plane {
  y, 0
  pigment { rgb <0.7, 0.7, 0.65> }
  finish { ambient rgb 0.1 / <0.7, 0.7, 0.65> diffuse 1 specular 0 phong 0 }
}
sphere {
  <-1.5 + 3 * clock, 1, 0>, 1
  pigment { rgb <0.8, 0.15, 0.1> }
  finish { ambient rgb <0.1, 0.02, 0.02> / <0.8, 0.15, 0.1> diffuse 1 specular 0 phong 0 }
}
