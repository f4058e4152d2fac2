// Hand-written POV-Ray 3.7 twin of sky-layers.xml (written from POV-Ray's documentation,
// not exported). Each <sky> layer is a sky_sphere pigment, in the same order (the last on
// top); the coordinates are Lucent's, seen through a mirrored camera (right -x).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb 0 }
camera {
  perspective
  location <0, 1.2, 6>
  right -x * 240 / 180
  up y
  angle 60
  look_at <0, 1.6, 0>
}
light_source { <-5, 8, 6> color rgb 1 }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0 rgb <0.75, 0.8, 0.95>]
      [0.5 rgb <0.2, 0.35, 0.85>]
      [1 rgb <0.05, 0.1, 0.45>]
    }
  }
  pigment {
    bozo
    turbulence 0.4
    color_map {
      [0 rgb 1]
      [0.35 rgbt <0.95, 0.95, 0.95, 0.2>]
      [0.6 rgbt <0.9, 0.9, 0.9, 1>]
      [1 rgbt <0.9, 0.9, 0.9, 1>]
    }
    scale <0.25, 0.08, 0.25>
  }
  pigment {
    gradient y
    color_map {
      [0 rgbft <1, 0.8, 0.6, 0.6, 0.2>]
      [0.3 rgbt <1, 1, 1, 1>]
    }
  }
}
plane { y, 0
  texture {
    pigment { checker rgb <0.85, 0.85, 0.8>, rgb <0.3, 0.35, 0.3> }
    finish { ambient 0.1 diffuse 0.8 specular 0 phong 0 reflection 0 }
  }
}
sphere { <0, 1.2, 0>, 1.2
  texture {
    pigment { rgb 1 }
    finish { ambient 0 diffuse 0.05 specular 0 phong 0 reflection 0.9 }
  }
}
