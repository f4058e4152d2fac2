// Hand-written POV-Ray 3.7 twin of gamma.xml, in linear colours (assumed_gamma 1.0).
// gamma_22.pov is this file with assumed_gamma 2.2.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 1.5, 5>
  right -x * 80 / 60
  up y
  angle 45
  look_at <0, 0.6, 0>
}
light_source { <-3, 5, 4> color rgb 1 }

plane { y, 0
  pigment { rgb 0.7 }
  finish { ambient 0.1 / 0.7 diffuse 1 specular 0 phong 0 reflection 0 }
}
sphere { <-0.8, 0.6, 0>, 0.6
  pigment { rgb <0.6, 0.2, 0.15> }
  finish { ambient rgb <0.05, 0.02, 0.02> / <0.6, 0.2, 0.15> diffuse 1 specular 0 phong 0 }
}
sphere { <0.8, 0.6, 0>, 0.6
  pigment { rgb <0.2, 0.3, 0.5> }
  finish {
    ambient rgb <0.02, 0.03, 0.05> / <0.2, 0.3, 0.5> diffuse 1
    specular 0.6 roughness 1 / 40 phong 0
  }
}
