// Hand-written POV-Ray 3.7 twin of fade.xml (written from POV-Ray's documentation, not
// exported). Lucent's clear solid (transmissive 1, nothing else) is a pigment with transmit
// 1; its fade-distance, fade-power and fade-color are the interior's keywords.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 8 adc_bailout 0.0039 }

#declare Clear = texture {
  pigment { rgbt <0, 0, 0, 1> }
  finish { ambient 0 diffuse 0 specular 0 phong 0 reflection 0 }
}

background { rgb <0.8, 0.82, 0.85> }
camera {
  perspective
  location <0, 2.4, 6>
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-2, 6, 5> color rgb 1 }

plane { y, 0
  texture {
    pigment { checker rgb 0.95, rgb 0.6 scale 0.5 }
    finish { ambient 0.2 diffuse 0.8 specular 0 phong 0 reflection 0 }
  }
}
sphere { <-1.4, 1, 0>, 1
  texture { Clear }
  interior { ior 1.5 fade_distance 0.8 fade_power 2 fade_color <0.9, 0.3, 0.1> }
}
box { <-0.4, 0.05, -1.2>, <0.4, 1.25, 1.2>
  texture { Clear }
  interior { ior 1 fade_distance 0.5 fade_power 1 fade_color <0.1, 0.4, 0.8> }
  rotate y * 35 translate <1.1, 0, 0>
}
sphere { <0.1, 0.45, 1.6>, 0.4
  texture { Clear }
  interior { ior 1 fade_distance 1 fade_power 0 fade_color <0.2, 0.8, 0.2> }
}
