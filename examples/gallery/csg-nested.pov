// csg-nested.xml exported by Lucent as a POV-Ray 3.7 scene.
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
  angle 40
  location <3.2, 2.6, 4.4>
  sky <0, 1, 0>
  look_at <0, 0, 0>
}

light_source {
  <5, 8, 6>
  color rgb <1, 1, 1>
}
light_source {
  <-6, 3, 2>
  color rgb <0.35, 0.35, 0.35>
}

// material 'blue' at csg-nested.xml:8:3
#declare M1_blue = texture {
  pigment { rgbft <0.15, 0.3, 0.85, 0, 0> }
  finish {
    ambient rgb <0.79999995, 0.39999998, 0.14117646>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.4
    roughness 0.016666666666666666
    reflection { rgb <0, 0, 0> }
  }
}
// material 'red' at csg-nested.xml:9:3
#declare M2_red = texture {
  pigment { rgbft <0.85, 0.15, 0.12, 0, 0> }
  finish {
    ambient rgb <0.14117646, 0.79999995, 1>
    emission rgb <0, 0, 0>
    diffuse 1
    brilliance 1
    phong 0
    specular 0.4
    roughness 0.016666666666666666
    reflection { rgb <0, 0, 0> }
  }
}
// material 'green' at csg-nested.xml:10:3
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

difference {  // <difference> csg-nested.xml:11:3
  intersection {  // <intersection> csg-nested.xml:12:5
    box {  // <box> csg-nested.xml:13:7
      <-1, -1, -1>, <1, 1, 1>
      texture { M2_red }
    }
    sphere {  // <sphere> csg-nested.xml:14:7
      <0, 0, 0>, 1.32
      texture { M1_blue }
    }
  }
  union {  // <union> csg-nested.xml:16:5
    cylinder {  // <cylinder> csg-nested.xml:17:7
      <-1.6, 0, 0>, <1.6, 0, 0>, 0.55
      texture { M3_green }
    }
    cylinder {  // <cylinder> csg-nested.xml:18:7
      <0, -1.6, 0>, <0, 1.6, 0>, 0.55
      texture { M3_green }
    }
    cylinder {  // <cylinder> csg-nested.xml:19:7
      <0, 0, -1.6>, <0, 0, 1.6>, 0.55
      texture { M3_green }
    }
  }
  matrix <0.9659258262890683, 0, -0.25881904510252074,  0, 1, 0,  0.25881904510252074, 0, 0.9659258262890683,  0, 0, 0>
}
