// Hand-written POV-Ray 3.7 twin of texture-averages.xml (written from POV-Ray's
// documentation, not exported). Each averaged <material-map> is `average texture_map`, its
// weights the entries' values; the map below is a gradient with a repeat warp and
// turbulence, whose texture_map entries POV-Ray evaluates at the warped point as Lucent
// does. The coordinates are Lucent's, seen through a mirrored camera (right -x). POV-Ray
// multiplies ambient by the pigment: a grey Lucent ambient on an untextured material is
// written divided by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 2.2, 8>
  right -x * 320 / 240
  up y
  angle 50
  look_at <0, 1.5, 0>
}
light_source { <-3, 6, 6> color rgb 1 }

#declare T_Marble = texture {
  pigment {
    marble
    turbulence 0.6
    color_map { [0 rgb <0.95, 0.95, 0.9>] [1 rgb <0.5, 0.2, 0.15>] }
    scale 0.5
  }
  finish { ambient 0.1 diffuse 1 }
}
#declare T_Radial = texture {
  pigment {
    radial
    frequency 8
    color_map { [0 rgb <0.9, 0.8, 0.2>] [0.5 rgb <0.2, 0.3, 0.8>] [1 rgb <0.9, 0.8, 0.2>] }
    rotate x * 90
  }
  finish { ambient 0.1 diffuse 1 phong 1 phong_size 40 }
}
#declare T_Glass = texture {
  pigment { rgbt <1, 1, 1, 0.9> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 reflection 0.05 }
}
#declare T_Mirror = texture {
  pigment { rgb 1 }
  finish { ambient 0.02 diffuse 0.1 reflection 0.8 }
}
#declare T_Plastic = texture {
  pigment { rgb <0.9, 0.4, 0.1> }
  normal { bumps 0.6 scale 0.12 }
  finish { ambient rgb <0.1 / 0.9, 0.25, 1> diffuse 1 phong 0.7 phong_size 60 }
}
// A layered texture: the green below, the stripes (clear where transmit is 1) over it.
#declare T_Striped =
  texture {
    pigment { rgb <0.2, 0.7, 0.3> }
    finish { ambient rgb <0.5, 0.1 / 0.7, 0.1 / 0.3> diffuse 1 }
  }
  texture {
    pigment {
      gradient y
      color_map {
        [0 rgbt <1, 1, 1, 1>]
        [0.6 rgbt <1, 1, 1, 1>]
        [0.6 rgb <0.1, 0.2, 0.6>]
        [1 rgb <0.1, 0.2, 0.6>]
      }
      scale 0.3
    }
    finish { ambient 0.1 diffuse 1 }
  }

plane { y, 0
  pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.35, 0.35, 0.4> }
  finish { ambient 0.1 diffuse 1 }
}
box { <-3.6, 1.6, -0.1>, <-1.6, 3.6, 0>
  texture { average texture_map { [3 T_Marble] [1 T_Radial] } }
}
sphere { <0, 2.6, 0>, 1
  texture { average texture_map { [1 T_Glass] [1 T_Mirror] [2 T_Plastic] } }
  interior { ior 1.5 }
}
box { <1.6, 1.6, -0.1>, <3.6, 3.6, 0>
  texture { average texture_map { [1 T_Striped] [1 T_Marble] } }
}
box { <-3, 0.2, 0.5>, <3, 1.3, 0.6>
  texture {
    gradient x
    turbulence 0.15
    warp { repeat x * 1.5 offset <0, 0.25, 0> flip x }
    texture_map {
      [0.2
        pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.6, 0.1, 0.1> scale 0.2 }
        finish { ambient 0.15 diffuse 1 }
      ]
      [0.8
        pigment {
          radial
          frequency 6
          color_map { [0 rgb <0.1, 0.5, 0.3>] [0.5 rgb <0.95, 0.9, 0.6>] [1 rgb <0.1, 0.5, 0.3>] }
          rotate x * 90
          translate <0.3, 0.75, 0>
        }
        finish { ambient 0.15 diffuse 1 }
      ]
    }
  }
}
