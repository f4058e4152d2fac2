// Hand-written POV-Ray 3.7 twin of finishes.xml (written from POV-Ray 3.7's documentation,
// not exported). Lucent's phong, phong-size, brilliance and metallic are POV-Ray's finish
// keywords of those names; Lucent's specular k_s with shininess n_s is POV-Ray's specular
// with roughness 1/n_s; ambient k_a becomes ambient k_a/k_d because POV-Ray multiplies
// ambient by the pigment, and the pigment carries k_d with diffuse 1 (metallic takes its
// tint from the pigment).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Each finish starts from Lucent's defaults: no highlight, brilliance 1, no reflection.
#declare Base = finish { diffuse 1 specular 0 phong 0 brilliance 1 reflection 0 }

background { rgb <0.25, 0.3, 0.4> }
camera {
  perspective
  location <0, 2.5, 11>
  right -x * 400 / 200
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <6, 5, 8> color rgb 0.4 }

plane { y, 0 texture { pigment { rgb <0.6, 0.6, 0.55> } finish { Base ambient rgb 0.1 / <0.6, 0.6, 0.55>  } } }
sphere { <-3.75, 0.7, 0>, 0.7 texture { pigment { rgb <0.8, 0.1, 0.1> } finish { Base ambient rgb 0.05 / <0.8, 0.1, 0.1> phong 0.8 phong_size 12 } } }
sphere { <-2.25, 0.7, 0>, 0.7 texture { pigment { rgb <0.1, 0.5, 0.1> } finish { Base ambient rgb 0.05 / <0.1, 0.5, 0.1> phong 1 phong_size 300 } } }
sphere { <-0.75, 0.7, 0>, 0.7 texture { pigment { rgb <0.8, 0.7, 0.3> } finish { Base ambient rgb 0.05 / <0.8, 0.7, 0.3> brilliance 0.5 } } }
sphere { <0.75, 0.7, 0>, 0.7 texture { pigment { rgb <0.8, 0.7, 0.3> } finish { Base ambient rgb 0.05 / <0.8, 0.7, 0.3> brilliance 4 } } }
sphere { <2.25, 0.7, 0>, 0.7
  texture { pigment { rgb <0.9, 0.65, 0.15> } finish { Base ambient rgb 0.05 / <0.9, 0.65, 0.15> specular 0.9 roughness 1 / 40 metallic } } }
sphere { <3.75, 0.7, 0>, 0.7 texture { pigment { rgb <0.75, 0.35, 0.2> } finish { Base ambient rgb 0.05 / <0.75, 0.35, 0.2> phong 0.9 phong_size 30 metallic } } }
