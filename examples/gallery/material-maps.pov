// Hand-written POV-Ray 3.7 twin of material-maps.xml (written from POV-Ray's documentation,
// not exported). Each <material-map> is a texture_map (or a checker of textures) whose
// entries are the materials' textures; the interior is the object's. POV-Ray evaluates an
// entry's patterns in the map's pattern space, Lucent in the object's, so the entries'
// transforms here undo the map's. The coordinates are Lucent's, seen through a mirrored
// camera (right -x). POV-Ray multiplies ambient by the pigment: a grey Lucent ambient on an
// untextured material is written divided by the pigment.
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

#declare T_Tile = texture {
  pigment { rgb <0.8, 0.75, 0.6> }
  finish { ambient rgb <0.1875, 0.2, 0.25> diffuse 1 }
}
#declare T_Mirror = texture {
  pigment { rgb 1 }
  finish { ambient 0.02 diffuse 0.1 reflection 0.7 }
}
#declare T_Glass = texture {
  pigment { rgbt <1, 1, 1, 0.9> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 reflection 0.05 }
}
// Lucent's bumps are scaled by 0.1 in the object's space: here in the map's (scale 2,
// then translate -0.1 y), so the map's transform is undone after the bumps' own.
#declare T_Plastic = texture {
  pigment { rgb <0.9, 0.4, 0.1> }
  normal { bumps 0.5 scale 0.1 translate <0, 0.1, 0> scale 0.5 }
  finish { ambient rgb <0.1 / 0.9, 0.25, 1> diffuse 1 phong 0.7 phong_size 60 }
}
// The box's map is bozo scaled by 0.4: its entries' transforms are divided by it.
#declare T_Green = texture {
  pigment { rgb <0.2, 0.7, 0.3> }
  finish { ambient rgb <0.5, 0.1 / 0.7, 0.1 / 0.3> diffuse 1 }
}
texture {
  pigment {
    gradient x
    color_map {
      [0 rgbt <1, 1, 1, 1>]
      [0.6 rgbt <1, 1, 1, 1>]
      [0.6 rgb <0.1, 0.2, 0.6>]
      [1 rgb <0.1, 0.2, 0.6>]
    }
    scale 0.3 / 0.4
  }
  finish { ambient 0.1 diffuse 1 }
}
#declare T_Marble = texture {
  pigment {
    marble
    turbulence 0.6
    color_map { [0 rgb <0.95, 0.95, 0.9>] [1 rgb <0.3, 0.3, 0.35>] }
    scale 0.5 / 0.4
  }
  finish { ambient 0.1 diffuse 1 }
}

plane { y, 0
  texture { checker texture { T_Tile } texture { T_Mirror } }
}
sphere { <-1.2, 1, 0.4>, 1
  texture {
    gradient y
    texture_map { [0.3 T_Glass] [0.7 T_Plastic] }
    scale 2
    translate <0, -0.1, 0>
  }
  interior { ior 1.4 }
}
box { <0.4, 0, -1>, <2.4, 1.8, 0.6>
  texture {
    bozo
    texture_map { [0.4 T_Green] [0.6 T_Marble] }
    scale 0.4
  }
}
