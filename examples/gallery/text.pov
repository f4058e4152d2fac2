// Hand-written POV-Ray 3.7 twin of text.xml (written from POV-Ray's documentation, not
// exported). A text object's glyphs stand on the xy-plane, baseline y = 0, one em = 1 unit,
// extruded from z = 0 to the thickness, as Lucent's <text>; the font is Lucent's default,
// DejaVu Sans. Lucent's material (k_a, k_d, specular k_s with shininess s) is pigment k_d,
// ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right vector is negated
// to keep Lucent's right-handed axes (the text then reads from +z, as in Lucent).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.6, 6.4>
  right -x*4/3
  up y
  angle 50
  look_at <0, 0.55, 0>
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
#declare Blue = Surface(<0.2, 0.45, 0.85>, <0.03, 0.06, 0.1>, 0.7, 60)
#declare Font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

plane { y, 0 texture { pigment { rgb 0.6 } finish { ambient 0.1 / 0.6 diffuse 1 specular 0 } } }

// A word whose o, e and 8 have holes.
text {
  ttf Font "Lucent 8oe" 0.25, 0
  texture { Gold }
  scale 0.9 translate <-2.55, 0, -1.4>
}

// A block with "CSG" cut through it.
difference {
  box { <-1.2, 0, -0.15>, <1.2, 0.8, 0.15> }
  text { ttf Font "CSG" 1, 0 scale 0.7 translate <-0.86, 0.14, -0.4> }
  texture { Blue }
  rotate y*-8 translate <0, 0, 1.5>
}
