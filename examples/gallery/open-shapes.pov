// Hand-written POV-Ray 3.7 twin of open-shapes.xml (written from POV-Ray's documentation,
// not exported). POV-Ray's height_field has neither walls nor a floor, and its lathe is open
// where its curve does not close: Lucent's open="true". Lucent's material (k_a, k_d,
// specular k_s with shininess s) is pigment k_d, ambient k_a / k_d, diffuse 1, specular k_s
// with roughness 1/s; the right vector is negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 0.9, 5>
  right -x*4/3
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
light_source { <3, -4, 5> color rgb 0.5 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

height_field {
  png "height-field.png"
  Surface(<0.2, 0.7, 0.3>, <0.03, 0.1, 0.04>, 0.4, 40)
  translate <-0.5, 0, -0.5> scale <2.2, 0.8, 2.2> rotate -20*x rotate 20*y translate <-1.1, 1.2, -0.8>
}
lathe {
  linear_spline 3, <0, 0>, <0.7, 0>, <0.8, 0.9>
  sturm
  Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
  rotate 55*x translate <1.2, 0.2, 0>
}
