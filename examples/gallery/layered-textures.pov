// Hand-written POV-Ray 3.7 twin of layered-textures.xml (written from POV-Ray's
// documentation, not exported). Each <layer> is a texture { } written after the one below
// it; the material's own terms are the first texture. The coordinates are Lucent's, seen
// through a mirrored camera (right -x). POV-Ray multiplies ambient by the pigment, so a
// grey Lucent ambient on an untextured material is written divided by the pigment.
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
    finish { ambient 0.15 diffuse 0.9 }
  }
}

sphere { <-1.3, 1, 0.4>, 1
  texture {
    pigment { rgb <1, 0.45, 0.1> }
    finish { ambient rgb <0.15, 0.15 / 0.45, 1.5> diffuse 1 phong 0.6 }
  }
  texture {
    pigment {
      gradient y
      color_map {
        [0 rgbf <0.1, 0.3, 1, 0.2>]
        [0.5 rgbf <0.1, 0.3, 1, 0.2>]
        [0.5 rgbt <1, 1, 1, 1>]
        [1 rgbt <1, 1, 1, 1>]
      }
      scale 0.5
    }
    finish { ambient 0.15 diffuse 0.8 }
  }
  texture {
    pigment {
      bozo
      color_map {
        [0 rgbt <1, 1, 1, 1>]
        [0.6 rgbt <1, 1, 1, 1>]
        [0.7 rgb <1, 1, 1>]
        [1 rgb <1, 1, 1>]
      }
      scale 0.3
    }
    normal { bumps 0.4 scale 0.15 }
    finish { ambient 0.2 diffuse 0.9 specular 0.8 roughness 0.025 }
  }
}

sphere { <1.2, 0.8, 1.2>, 0.8
  texture {
    pigment { rgbt <0.25, 0.75, 0.375, 0.6> }
    finish { ambient 0.5 diffuse 1 }
  }
  texture {
    pigment {
      gradient x
      color_map {
        [0 rgb <0.9, 0.9, 0.2>]
        [0.3 rgb <0.9, 0.9, 0.2>]
        [0.3 rgbt <1, 1, 1, 1>]
        [1 rgbt <1, 1, 1, 1>]
      }
      scale 0.4
    }
    finish { ambient 0.1 diffuse 0.9 }
  }
  interior { ior 1.3 }
}

box { <0.2, 0, -1.6>, <2.4, 1.6, -0.6>
  texture {
    pigment { checker rgb <0.9, 0.2, 0.2>, rgb <0.95, 0.95, 0.9> scale 0.4 }
    finish { ambient 0.15 diffuse 1 reflection 0.3 }
  }
  texture {
    pigment {
      marble
      turbulence 0.5
      color_map {
        [0 rgbf <0.2, 0.2, 0.3, 0.5>]
        [0.4 rgbt <1, 1, 1, 1>]
        [1 rgbt <0.1, 0.6, 0.2, 0.3>]
      }
      scale 0.6
    }
    finish { ambient 0.15 diffuse 1 }
  }
}
