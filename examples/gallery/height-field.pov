// Hand-written POV-Ray 3.7 twin of height-field.xml (written from POV-Ray's documentation,
// not exported). height_field { png "file" } spans <0, 0, 0> to <1, 1, 1> as Lucent's
// <height-field> does (the image's top row at z = 1); smooth and water_level are the same
// words. Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is
// negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.6, 6.4>
  right -x*4/3
  up y
  angle 46
  look_at <0, 0.3, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
light_source { <5, 4, 4> color rgb 0.35 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end
#declare Gold = Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
#declare Green = Surface(<0.2, 0.7, 0.3>, <0.03, 0.1, 0.04>, 0.4, 40)
#declare Blue = Surface(<0.2, 0.45, 0.85>, <0.03, 0.06, 0.1>, 0.7, 60)

plane { y, -0.02 texture { pigment { rgb 0.6 } finish { ambient 0.1 / 0.6 diffuse 1 specular 0 } } }

// Flat triangles.
height_field {
  png "height-field.png"
  texture { Green }
  translate <-0.5, 0, -0.5> scale <2.2, 1.2, 2.2> rotate 20*y translate <-1.35, 0, -0.9>
}
// Smooth normals.
height_field {
  png "height-field.png" smooth
  texture { Gold }
  translate <-0.5, 0, -0.5> scale <2.2, 1.2, 2.2> rotate -20*y translate <1.35, 0, -0.9>
}
// Below the water level removed, a ball cut out.
difference {
  height_field { png "height-field.png" smooth water_level 0.1 }
  sphere { <0.68, 0.62, 0.62>, 0.22 texture { Gold } }
  texture { Blue }
  translate <-0.5, 0, -0.5> scale <1.8, 0.9, 1.8> translate <0, 0, 1.5>
}
