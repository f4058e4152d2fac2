// Hand-written POV-Ray 3.7 twin of filter-transmit.xml (written from POV-Ray's
// documentation, not exported). A colour map entry's filter and transmit are POV-Ray's
// rgbf/rgbt colours; the coordinates are Lucent's, seen through a mirrored camera
// (right -x). With a texture Lucent's diffuse defaults to 1, and a one-number ambient is
// scaled by the texture colour, as POV-Ray scales ambient by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 2.4, 6.5>
  right -x * 240 / 180
  up y
  angle 50
  look_at <0, 0.9, 0>
}
light_source { <-3, 6, 5> color rgb 1 }

plane { y, 0
  texture {
    pigment { checker rgb <0.9, 0.9, 0.85>, rgb <0.25, 0.3, 0.35> }
    finish { ambient 0.15 diffuse 0.9 specular 0 phong 0 reflection 0 }
  }
}
sphere { <-1.1, 1, 0.6>, 1
  texture {
    pigment {
      gradient y
      color_map {
        [0 rgb <1, 0.45, 0.1>]
        [0.3 rgb <1, 0.45, 0.1>]
        [0.5 rgbf <0.2, 0.5, 1, 0.85>]
        [0.75 rgbf <0.2, 0.5, 1, 0.85>]
        [0.9 rgbt <1, 1, 1, 0.9>]
        [1 rgbt <1, 1, 1, 0.9>]
      }
      scale 0.7
    }
    finish { ambient 0.15 diffuse 1 specular 0 phong 0.5 reflection 0 }
  }
}
box { <0.3, 0, -0.6>, <2.5, 2, -0.5>
  texture {
    pigment {
      hexagon rgb <0.9, 0.85, 0.7>, rgbf <0.9, 0.1, 0.1, 0.7>, rgbt <1, 1, 1, 1>
      rotate x * 90
      scale 0.35
    }
    finish { ambient 0.15 diffuse 1 specular 0 phong 0 reflection 0 }
  }
}
