// torus.xml exported by Lucent as a POV-Ray 3.7 scene.
// Render: povray +I<this file> +W320 +H240 -A   (+FN writes sRGB, File_Gamma=1.0 linear)
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 5
  adc_bailout 0.0039
  ambient_light rgb <1, 1, 1>
}
background { rgb <0.15, 0.2, 0.25> }

camera {
  perspective
  right -x*320/240
  up y
  angle 50
  location <0, 3.2, 6>
  sky <0, 1, 0>
  look_at <0, 0.8, 0>
}

light_source {
  <-4, 6, 5>
  color rgb <1, 1, 1>
}
light_source {
  <4, 5, 3>
  color rgb <0.3, 0.3, 0.3>
}

// the inline material at torus.xml:9:5
#declare M1 = texture {
  pigment { rgbft <1, 1, 1, 0, 0> }
  finish {
    ambient rgb <0.1, 0.1, 0.1>
    emission rgb <0, 0, 0>
    diffuse 0.65
    brilliance 1
    phong 0
    specular 0
    roughness 0.015625
    reflection { rgb <0, 0, 0> }
  }
}
// the inline material at torus.xml:12:5
#declare M2 = texture {
  pigment { rgbft <0.8, 0.55, 0.15, 0, 0> }
  finish {
    ambient rgb <0.125, 0.12727273, 0.13333333>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.8
    roughness 0.0125
    reflection { rgb <0, 0, 0> }
  }
}
// the inline material at torus.xml:15:5
#declare M3 = texture {
  pigment { rgbft <0.2, 0.5, 0.8, 0, 0> }
  finish {
    ambient rgb <0.14999999, 0.12, 0.125>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.8
    roughness 0.0125
    reflection { rgb <0, 0, 0> }
  }
}

plane {  // <plane> torus.xml:8:3
  <0, 1, 0>, 0
  texture { M1 }
}
torus {  // <torus> torus.xml:11:3
  1.1, 0.3
  texture { M2 }
  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  -0.5, 0.3, 0>
}
torus {  // <torus> torus.xml:14:3
  1, 0.25
  texture { M3 }
  matrix <0.9396926207859084, 0, -0.3420201433256687,  0.3420201433256687, 0, 0.9396926207859084,  0, -1, 0,  0.5, 1.3, 0>
}
