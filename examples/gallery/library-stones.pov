// Hand-written POV-Ray 3.7 twin of library-stones.xml (written from POV-Ray 3.7's
// documentation and library/stones.xml, not exported). Each library stone is one POV-Ray
// pigment pattern (granite, marble, agate, a turbulent gradient, bozo) with its colour map,
// turbulence and scale; the spheres use center="...", so the patterns sit in world space.
// Lucent's diffuse and single-number ambient are multiplied by the pattern's colour, as
// POV-Ray's diffuse and ambient multiply the pigment; specular k_s with shininess n_s is
// specular k_s with roughness 1/n_s, reflective k_r is reflection k_r.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0.0039 }

background { rgb <0.55, 0.65, 0.85> }
camera {
  perspective
  location <0, 5, 10>
  right -x * 400 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 46
  look_at <0, 0.4, 0.2>
}
light_source { <-5, 9, 7> color rgb 1 }
light_source { <6, 4, 6> color rgb 0.3 }

// A stone's finish: ambient 0.1, diffuse 0.8, a highlight Ks of roughness R, reflection Kr.
#macro Stone(Ks, R, Kr)
  finish { ambient 0.1 diffuse 0.8 brilliance 1 specular Ks roughness R phong 0 reflection Kr }
#end
#declare Polished = Stone(0.5, 1 / 100, 0.05)

// The floor: lucent:woods.xml's dark oak.
plane {
  y, 0
  texture {
    pigment {
      wood turbulence 0.04 octaves 3
      color_map { [0.1 rgb <0.6, 0.3, 0.18>] [0.9 rgb <0.3, 0.15, 0.09>] }
      scale <0.2, 0.2, 1> rotate 3 * x rotate 2 * y
    }
    Stone(0.15, 1 / 30, 0)
  }
}

// Back row: granite, pink granite, black granite, white, red and green marble.
sphere {
  <-3.5, 0.6, -0.8>, 0.6
  texture {
    pigment {
      granite
      color_map {
        [0.2  rgb <0.04, 0.04, 0.05>]
        [0.27 rgb <0.3, 0.3, 0.32>]
        [0.4  rgb <0.55, 0.55, 0.56>]
        [0.5  rgb <0.42, 0.42, 0.44>]
        [0.6  rgb <0.75, 0.74, 0.72>]
        [0.7  rgb <0.9, 0.89, 0.87>]
        [0.8  rgb <0.6, 0.6, 0.6>]
      }
      scale 0.35
    }
    Stone(0.3, 1 / 60, 0)
  }
}
sphere {
  <-2.1, 0.6, -0.8>, 0.6
  texture {
    pigment {
      granite
      color_map {
        [0.25 rgb 0]
        [0.25 rgb <0.85, 0.85, 0.95>]
        [0.3  rgb <0.85, 0.85, 0.95>]
        [0.35 rgb <0.75, 0.75, 0.75>]
        [0.4  rgb <0.82, 0.57, 0.46>]
        [0.65 rgb <0.82, 0.57, 0.46>]
        [0.85 rgb <1, 0.5, 0>]
      }
      scale 0.4
    }
    Stone(0.3, 1 / 60, 0)
  }
}
sphere {
  <-0.7, 0.6, -0.8>, 0.6
  texture {
    pigment {
      granite turbulence 0.6
      color_map {
        [0     rgb <0.161, 0.133, 0.118>]
        [0.104 rgb <0.11, 0.082, 0.071>]
        [0.252 rgb <0.161, 0.133, 0.118>]
        [0.383 rgb 0]
        [0.643 rgb <0.161, 0.133, 0.118>]
        [0.783 rgb <0.22, 0.149, 0.137>]
        [0.922 rgb 0]
        [0.983 rgb <0.22, 0.149, 0.137>]
        [1     rgb <0.161, 0.133, 0.118>]
      }
    }
    Stone(0.5, 1 / 120, 0.06)
  }
}
sphere {
  <0.7, 0.6, -0.8>, 0.6
  texture {
    pigment { marble turbulence 1 color_map { [0 rgb 0.9] [0.8 rgb 0.5] [1 rgb 0.2] } }
    finish { Polished }
  }
}
sphere {
  <2.1, 0.6, -0.8>, 0.6
  texture {
    pigment { marble turbulence 1 color_map { [0 rgb <0.8, 0.8, 0.6>] [0.8 rgb <0.8, 0.4, 0.4>] [1 rgb <0.8, 0.2, 0.2>] } }
    finish { Polished }
  }
}
sphere {
  <3.5, 0.6, -0.8>, 0.6
  texture {
    pigment {
      marble turbulence 1.2
      color_map {
        [0    rgb <0.04, 0.22, 0.1>]
        [0.6  rgb <0.08, 0.32, 0.16>]
        [0.85 rgb <0.15, 0.4, 0.25>]
        [0.95 rgb <0.75, 0.85, 0.75>]
        [1    rgb <0.9, 0.95, 0.9>]
      }
      scale 0.8
    }
    finish { Polished }
  }
}

// Front row: jade, brown and blue agate, sandstone, slate, rose granite.
sphere {
  <-3.5, 0.6, 1.2>, 0.6
  texture {
    pigment {
      marble turbulence 1.8
      color_map { [0 rgb <0.1, 0.6, 0.1>] [0.8 rgb <0, 0.3, 0>] [0.8 rgb <0.1, 0.6, 0.1>] [1 rgb <0, 0.2, 0>] }
    }
    Stone(0.6, 1 / 150, 0.04)
  }
}
sphere {
  <-2.1, 0.6, 1.2>, 0.6
  texture {
    pigment { agate color_map { [0 rgb 0] [0.5 rgb <0.9, 0.7, 0.6>] [0.6 rgb <0.9, 0.7, 0.4>] [1 rgb <0.7, 0.4, 0.2>] } }
    Stone(0.5, 1 / 100, 0.04)
  }
}
sphere {
  <-0.7, 0.6, 1.2>, 0.6
  texture {
    pigment {
      agate
      color_map {
        [0.5  rgb <0.3, 0.3, 0.5>]
        [0.55 rgb <0.2, 0.2, 0.3>]
        [0.6  rgb <0.25, 0.25, 0.35>]
        [0.7  rgb <0.15, 0.15, 0.26>]
        [0.8  rgb <0.1, 0.1, 0.2>]
        [0.9  rgb <0.3, 0.3, 0.5>]
        [1    rgb <0.1, 0.1, 0.2>]
      }
    }
    Stone(0.5, 1 / 100, 0.04)
  }
}
sphere {
  <0.7, 0.6, 1.2>, 0.6
  texture {
    pigment {
      gradient y turbulence 0.5 octaves 4
      color_map {
        [0    rgb <0.82, 0.66, 0.45>]
        [0.25 rgb <0.75, 0.55, 0.35>]
        [0.45 rgb <0.86, 0.72, 0.52>]
        [0.6  rgb <0.7, 0.45, 0.28>]
        [0.8  rgb <0.8, 0.62, 0.42>]
        [1    rgb <0.82, 0.66, 0.45>]
      }
      scale 0.4
    }
    Stone(0, 1 / 64, 0)
  }
}
sphere {
  <2.1, 0.6, 1.2>, 0.6
  texture {
    pigment {
      bozo turbulence 0.6
      color_map { [0 rgb <0.17, 0.19, 0.22>] [0.5 rgb <0.23, 0.25, 0.28>] [1 rgb <0.3, 0.31, 0.33>] }
      scale <0.3, 0.05, 0.3>
    }
    Stone(0.05, 1 / 10, 0)
  }
}
sphere {
  <3.5, 0.6, 1.2>, 0.6
  texture {
    pigment {
      granite turbulence 0.4
      color_map {
        [0     rgb <0.729, 0.502, 0.451>]
        [0.153 rgb <0.769, 0.686, 0.592>]
        [0.398 rgb <0.843, 0.753, 0.718>]
        [0.559 rgb <0.78, 0.667, 0.561>]
        [0.729 rgb <0.741, 0.659, 0.576>]
        [1     rgb <0.729, 0.502, 0.451>]
      }
    }
    Stone(0.3, 1 / 60, 0)
  }
}
