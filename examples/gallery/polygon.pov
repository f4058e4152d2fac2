// Hand-written POV-Ray 3.7 twin of polygon.xml (written from POV-Ray's documentation, not
// exported). Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 0.5, 5>
  right -x*4/3
  up y
  angle 50
  look_at <0, 0.3, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
light_source { <3, 2, 5> color rgb 0.5 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

// A pentagram: its outline crosses itself, and the even-odd rule leaves the centre out.
polygon {
  6, <0, 1>, <0.5878, -0.809>, <-0.9511, 0.309>, <0.9511, 0.309>, <-0.5878, -0.809>, <0, 1>
  Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
  rotate -25*y translate <-1.1, 0.5, 0>
}
// A square frame: a second outline inside the first is a hole.
polygon {
  10,
  <-0.9, -0.9>, <0.9, -0.9>, <0.9, 0.9>, <-0.9, 0.9>, <-0.9, -0.9>,
  <-0.4, -0.5>, <0.5, -0.4>, <0.4, 0.5>, <-0.5, 0.4>, <-0.4, -0.5>
  Surface(<0.2, 0.35, 0.8>, <0.02, 0.04, 0.1>, 0.4, 40)
  rotate -30*x rotate 35*y translate <1.2, 0.4, 0>
}
plane {
  y, -1
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}
