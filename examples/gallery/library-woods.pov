// Hand-written POV-Ray 3.7 twin of library-woods.xml (written from POV-Ray 3.7's
// documentation and library/woods.xml, not exported). Each library wood is POV-Ray's wood
// pigment with its turbulence, octaves, colour map and transform (scale, then the tilts), as in
// POV-Ray's woods.inc; the spheres use center="...", so the patterns sit in world space.
// Lucent's diffuse and single-number ambient are multiplied by the pattern's colour, as
// POV-Ray's diffuse and ambient multiply the pigment; specular k_s with shininess n_s is
// specular k_s with roughness 1/n_s.
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

// The oiled finish of the woods: ambient 0.1, diffuse 0.8 and a dull sheen of size 1/R.
#macro Oiled(Ks, R)
  finish { ambient 0.1 diffuse 0.8 brilliance 1 specular Ks roughness R phong 0 reflection 0 }
#end

// The floor: lucent:stones.xml's slate, squashed bozo clouds in dark blue-greys, matte.
plane {
  y, 0
  texture {
    pigment {
      bozo turbulence 0.6
      color_map { [0 rgb <0.17, 0.19, 0.22>] [0.5 rgb <0.23, 0.25, 0.28>] [1 rgb <0.3, 0.31, 0.33>] }
      scale <0.3, 0.05, 0.3>
    }
    Oiled(0.05, 1 / 10)
  }
}

// Back row: oak, dark oak, pine, cherry.
sphere {
  <-3.3, 0.7, -0.8>, 0.7
  texture {
    pigment {
      wood turbulence 0.04 octaves 3
      color_map { [0.1 rgb <0.88, 0.6, 0.3>] [0.9 rgb <0.6, 0.4, 0.2>] }
      scale <0.08, 0.08, 1> rotate 3 * x rotate 2 * y
    }
    Oiled(0.15, 1 / 30)
  }
}
sphere {
  <-1.1, 0.7, -0.8>, 0.7
  texture {
    pigment {
      wood turbulence 0.04 octaves 3
      color_map { [0.1 rgb <0.6, 0.3, 0.18>] [0.9 rgb <0.3, 0.15, 0.09>] }
      scale <0.2, 0.2, 1> rotate 3 * x rotate 2 * y
    }
    Oiled(0.15, 1 / 30)
  }
}
sphere {
  <1.1, 0.7, -0.8>, 0.7
  texture {
    pigment {
      wood turbulence 0.02
      color_map {
        [0.222 rgb <0.808, 0.671, 0.251>]
        [0.342 rgb <0.6, 0.349, 0.043>]
        [0.393 rgb <0.808, 0.671, 0.251>]
        [0.709 rgb <0.808, 0.671, 0.251>]
        [0.821 rgb <0.533, 0.298, 0.027>]
        [1     rgb <0.808, 0.671, 0.251>]
      }
      scale <0.15, 0.15, 1> rotate 4 * x rotate 2 * y
    }
    Oiled(0.1, 1 / 20)
  }
}
sphere {
  <3.3, 0.7, -0.8>, 0.7
  texture {
    pigment {
      wood turbulence 0.08 octaves 4
      color_map { [0.8 rgb <0.66, 0.31, 0.2>] [0.8 rgb <0.4, 0.13, 0.06>] [1 rgb <0.2, 0.06, 0.03>] }
      scale <0.2, 0.2, 1> rotate 3 * x rotate 2 * y
    }
    Oiled(0.2, 1 / 40)
  }
}

// Front row: walnut, mahogany, birch, teak.
sphere {
  <-3.3, 0.7, 1.2>, 0.7
  texture {
    pigment {
      wood turbulence 0.05 octaves 4
      color_map {
        [0    rgb <0.36, 0.22, 0.13>]
        [0.5  rgb <0.3, 0.17, 0.1>]
        [0.85 rgb <0.17, 0.09, 0.05>]
        [1    rgb <0.25, 0.14, 0.08>]
      }
      scale <0.1, 0.1, 1> rotate 3 * x rotate 3 * y
    }
    Oiled(0.2, 1 / 40)
  }
}
sphere {
  <-1.1, 0.7, 1.2>, 0.7
  texture {
    pigment {
      wood turbulence 0.05 octaves 2
      color_map {
        [0   rgb <0.3, 0.1, 0.15>]
        [0.3 rgb <0.3, 0.15, 0.15>]
        [0.6 rgb <0.5, 0.2, 0.15>]
        [1   rgb <0.3, 0.1, 0.15>]
      }
      scale <0.15, 0.15, 1> rotate 2 * x
    }
    Oiled(0.2, 1 / 40)
  }
}
sphere {
  <1.1, 0.7, 1.2>, 0.7
  texture {
    pigment {
      wood turbulence 0.04 octaves 3
      color_map {
        [0   rgb <0.93, 0.82, 0.64>]
        [0.8 rgb <0.96, 0.87, 0.7>]
        [0.8 rgb <0.78, 0.6, 0.42>]
        [1   rgb <0.86, 0.72, 0.52>]
      }
      scale <0.12, 0.12, 1> rotate 3 * x rotate 2 * y
    }
    Oiled(0.1, 1 / 20)
  }
}
sphere {
  <3.3, 0.7, 1.2>, 0.7
  texture {
    pigment {
      wood turbulence 0.08 octaves 4
      color_map { [0.8 rgb <0.7, 0.42, 0.16>] [0.8 rgb <0.5, 0.28, 0.1>] [1 rgb <0.35, 0.18, 0.06>] }
      scale <0.25, 0.25, 1> rotate 3 * x rotate -2 * y
    }
    Oiled(0.15, 1 / 30)
  }
}
