// csg-halfspace.xml exported by Lucent as a POV-Ray 3.7 scene.
// Render: povray +I<this file> +W320 +H240 -A   (+FN writes sRGB, File_Gamma=1.0 linear)
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 5
  adc_bailout 0.0039
  ambient_light rgb <1, 1, 1>
}
background { rgb <0.1, 0.12, 0.16> }

camera {
  perspective
  right -x*320/240
  up y
  angle 44
  location <0, 3, 5.6>
  sky <0, 1, 0>
  look_at <0, 0.7, 0>
}

light_source {
  <4, 9, 7>
  color rgb <1, 1, 1>
}
light_source {
  <-7, 4, 3>
  color rgb <0.3, 0.3, 0.3>
}

// material 'orange' at csg-halfspace.xml:8:3
#declare M1_orange = texture {
  pigment { rgbft <0.9, 0.45, 0.1, 0, 0> }
  finish {
    ambient rgb <0.13333334, 0.26666668, 1.1999999>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.4
    roughness 0.016666666666666666
    reflection { rgb <0, 0, 0> }
  }
}
// material 'cut' at csg-halfspace.xml:9:3
#declare M2_cut = texture {
  pigment { rgbft <0.95, 0.9, 0.75, 0, 0> }
  finish {
    ambient rgb <0.12631579, 0.13333334, 0.16>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.4
    roughness 0.016666666666666666
    reflection { rgb <0, 0, 0> }
  }
}
// material 'green' at csg-halfspace.xml:10:3
#declare M3_green = texture {
  pigment { rgbft <0.2, 0.7, 0.25, 0, 0> }
  finish {
    ambient rgb <0.59999996, 0.17142858, 0.48>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.4
    roughness 0.016666666666666666
    reflection { rgb <0, 0, 0> }
  }
}
// the inline material at csg-halfspace.xml:12:5
#declare M4 = texture {
  pigment {
    checker
    rgbft <0.55, 0.55, 0.55, 0, 0>,
    rgbft <0.35, 0.35, 0.35, 0, 0>
  }
  finish {
    ambient rgb <0.12, 0.12, 0.12>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0
    roughness 0.015625
    reflection { rgb <0, 0, 0> }
  }
}

plane {  // <plane> csg-halfspace.xml:11:3
  <0, 1, 0>, -0.0001
  texture { M4 }
}
difference {  // <difference> csg-halfspace.xml:16:3
  sphere {  // <sphere> csg-halfspace.xml:17:5
    <0, 0, 0>, 0.9
    texture { M1_orange }
  }
  plane {  // <plane> csg-halfspace.xml:18:5
    <0.3244428422615251, -0.8111071056538127, -0.4866642633922876>, 0.15
    texture { M2_cut }
  }
  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  -1.3, 0.9, 0>
}
intersection {  // <intersection> csg-halfspace.xml:20:3
  box {  // <box> csg-halfspace.xml:21:5
    <-0.75, -0.75, -0.75>, <0.75, 0.75, 0.75>
    texture { M3_green }
  }
  plane {  // <plane> csg-halfspace.xml:22:5
    <0, 0.7071067811865475, 0.7071067811865475>, 0.5
    texture { M2_cut }
  }
  plane {  // <plane> csg-halfspace.xml:23:5
    <0.7071067811865475, 0.7071067811865475, 0>, 0.6
    texture { M2_cut }
  }
  matrix <0.9063077870366499, 0, 0.42261826174069944,  0, 1, 0,  -0.42261826174069944, 0, 0.9063077870366499,  1.3, 0.75, 0>
}
