// cones.xml exported by Lucent as a POV-Ray 3.7 scene.
// Render: povray +I<this file> +W320 +H240 -A   (+FN writes sRGB, File_Gamma=1.0 linear)
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 5
  adc_bailout 0.0039
  ambient_light rgb <1, 1, 1>
}
background { rgb <0.25, 0.2, 0.3> }

camera {
  perspective
  right -x*320/240
  up y
  angle 50
  location <0, 3.5, 7>
  sky <0, 1, 0>
  look_at <0, 0.8, 0>
}

light_source {
  <-3, 6, 6>
  color rgb <1, 1, 1>
}
light_source {
  <4, 4, 3>
  color rgb <0.35, 0.35, 0.35>
}

// the inline material at cones.xml:9:5
#declare M1 = texture {
  pigment { rgbft <0.6, 0.62, 0.6, 0, 0> }
  finish {
    ambient rgb <0.16666666, 0.16129032, 0.16666666>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0
    roughness 0.015625
    reflection { rgb <0, 0, 0> }
  }
}
// the inline material at cones.xml:12:5
#declare M2 = texture {
  pigment { rgbft <0.8, 0.25, 0.2, 0, 0> }
  finish {
    ambient rgb <0.125, 0.12, 0.14999999>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.5
    roughness 0.02
    reflection { rgb <0, 0, 0> }
  }
}
// the inline material at cones.xml:15:5
#declare M3 = texture {
  pigment { rgbft <0.25, 0.45, 0.85, 0, 0> }
  finish {
    ambient rgb <0.12, 0.11111112, 0.11764706>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.5
    roughness 0.02
    reflection { rgb <0, 0, 0> }
  }
}
// the inline material at cones.xml:18:5
#declare M4 = texture {
  pigment { rgbft <0.85, 0.8, 0.3, 0, 0> }
  finish {
    ambient rgb <0.11764706, 0.125, 0.099999994>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.4
    roughness 0.03333333333333333
    reflection { rgb <0, 0, 0> }
  }
}

plane {  // <plane> cones.xml:8:3
  <0, 1, 0>, 0
  texture { M1 }
}
cone {  // <cone> cones.xml:11:3
  <-2, 0, -0.5>, 0.8, <-2, 2, -0.5>, 0
  texture { M2 }
}
cone {  // <cone> cones.xml:14:3
  <0, 0, 0.5>, 0.8, <0, 1.1, 0.5>, 0.4
  texture { M3 }
}
cone {  // <cone> cones.xml:17:3
  <2, 0.3, -0.6>, 0.35, <2.2, 1.6, 0.4>, 0.75
  open
  texture { M4 }
}
