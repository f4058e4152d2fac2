// Hand-written POV-Ray 3.7 twin of pigment-maps.xml (written from POV-Ray's documentation,
// not exported). Lucent's <pigment-map>, <pigment-list> and <average> are POV-Ray's
// pigment_map, a block pattern's list of pigments and `average pigment_map`; a nested
// pigment's transforms compose with the outer one's, as POV-Ray evaluates the entries at
// the outer pattern's point. <normal type="average"> is `average normal_map`. The
// coordinates are Lucent's, seen through a mirrored camera (right -x). With a texture
// Lucent's diffuse defaults to 1, and a one-number ambient is scaled by the texture colour.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.45, 0.55, 0.7> }
camera {
  perspective
  location <0, 3.2, 6.5>
  right -x * 240 / 180
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-3, 6, 5> color rgb 1 }
light_source { <-0.5, 1, 0.3> * 10000 color rgb 0.3 parallel point_at <0, 0, 0> }

plane { y, 0
  texture {
    pigment {
      checker
      pigment { gradient x color_map { [0 rgb <0.9, 0.85, 0.6>] [1 rgb <0.3, 0.25, 0.2>] } scale 0.5 }
      pigment { rgbt <0.25, 0.35, 0.45, 0.5> }
      scale 1.5
    }
    finish { ambient 0.15 diffuse 0.9 specular 0 phong 0 reflection 0 }
  }
}
sphere { <0, 0, 0>, 0.8
  texture {
    pigment {
      gradient y
      pigment_map {
        [0.2 checker rgb <0.95, 0.8, 0.2>, rgb <0.7, 0.15, 0.1> scale 0.25]
        [0.5 marble color_map { [0 rgb <0.9, 0.9, 0.95>] [1 rgb <0.2, 0.3, 0.6>] } scale 0.4]
        [0.8 rgb <0.2, 0.8, 0.3>]
      }
      translate <0, -0.8, 0> / 1.6
      scale 1.6
    }
    finish { ambient 0.15 diffuse 1 specular 0.4 roughness 1 / 40 phong 0 reflection 0 }
  }
  translate <-1.9, 0.8, -0.3>
}
box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6>
  texture {
    pigment {
      average
      pigment_map {
        [1 gradient x color_map { [0 rgb <1, 0.2, 0.1>] [1 rgb <1, 1, 0.2>] } scale 0.6]
        [3 onion color_map { [0 rgb <0.1, 0.3, 0.9>] [1 rgb <0.9, 0.9, 0.9>] } scale 0.3]
      }
      rotate z * 20
    }
    finish { ambient 0.15 diffuse 1 specular 0 phong 0 reflection 0 }
  }
  rotate y * 30
  translate <0, 0.6, -0.6>
}
sphere { <0, 0, 0>, 0.8
  texture {
    pigment {
      hexagon
      pigment { rgb <0.9, 0.9, 0.85> }
      pigment {
        radial
        color_map { [0 rgb <0.8, 0.1, 0.1>] [0.5 rgb <0.9, 0.8, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
        rotate x * 90
      }
      pigment { checker rgb <0.1, 0.4, 0.2>, rgb <0.6, 0.9, 0.6> scale 0.3 }
      scale 0.25
      rotate x * 90
    }
    normal {
      average
      normal_map {
        [2 bumps 0.6 accuracy 0.02 scale 0.15]
        [1 ripples 0.8 accuracy 0.02 scale 0.3]
      }
    }
    finish { ambient 0.15 diffuse 1 specular 0.5 roughness 1 / 60 phong 0 reflection 0 }
  }
  translate <1.9, 0.8, -0.3>
}
