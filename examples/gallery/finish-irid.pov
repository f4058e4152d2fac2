// Hand-written POV-Ray 3.7 twin of finish-irid.xml (written from POV-Ray 3.7's documentation,
// not exported). Lucent's irid, irid-thickness and irid-turbulence are POV-Ray's
// irid { amount thickness t turbulence u }, with POV-Ray's default irid_wavelength. A grey
// diffuse k_d is POV-Ray's diffuse with a white pigment, so ambient stays k_a; specular k_s
// with shininess n_s is specular k_s with roughness 1/n_s.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Each finish starts from Lucent's defaults: no highlight, brilliance 1, no reflection.
#declare Base = finish { specular 0 phong 0 brilliance 1 reflection 0 }

background { rgb <0.12, 0.12, 0.16> }
camera {
  perspective
  location <0, 1.6, 7>
  right -x * 320 / 180
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-4, 6, 6> color rgb 1 }
light_source { <5, 4, 5> color rgb 0.4 }

plane { y, 0 texture { pigment { rgb 1 } finish { Base ambient 0.1 diffuse 0.5 } } }
sphere { <-2.3, 0.9, 0>, 0.9
  texture { pigment { rgb 1 } finish { Base ambient 0.05 diffuse 0.7 irid { 0.5 thickness 0.5 } } } }
sphere { <0, 0.9, 0>, 0.9
  texture { pigment { rgb 1 }
    finish { Base ambient 0.05 diffuse 0.3 phong 0.8 phong_size 60
             irid { 0.6 thickness 0.35 turbulence 0.8 } } } }
sphere { <2.3, 0.9, 0>, 0.9
  texture { pigment { rgb 1 }
    finish { Base ambient 0 diffuse 0.1 specular 0.6 roughness 1 / 80 reflection { rgb 0.6 }
             irid { 0.5 thickness 0.25 } } } }
