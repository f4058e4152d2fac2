// material_map as POV-Ray 3.7 picks its textures, seen straight on: five flat textures
// (ambient only) chosen by a 6 x 4 palette image's indices 0..15 (past five: modulo five,
// five itself the last), by an RGB image's red x 255 (8 and 16 bits; three textures once),
// with each interpolation of the palette (indices blended and truncated), once (texture 0 off
// the image), and palette bump maps with use_index (the indices themselves as heights). An
// image without a palette is not interpolated here: POV-Ray blends its pixels' -1s, whose sum
// lands on -1 or just above it (then number 0) by the last bit of the point.
// Images: make_material_maps.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  orthographic
  location <1.8, 1.8, -5>
  look_at <1.8, 1.8, 0>
  right x*3.6
  up y*3.6
}
light_source { <-3, 6, -8> color rgb 1 }
background { rgb 0.1 }
#macro Flat(C) texture { pigment { rgb C } finish { ambient 1 diffuse 0 } } #end
#macro Five()
  Flat(<1, 0, 0>) Flat(<0, 1, 0>) Flat(<0, 0, 1>) Flat(<1, 1, 0>) Flat(<0.5, 0.5, 0.5>)
#end
#macro At(Col, Row) translate <0.1 + 1.2*Col, 0.1 + 1.2*Row, 0> #end
#declare Unit = box { <0, 0, 0>, <1, 1, 0.1> }
object { Unit texture { material_map { png "mm_palette.png" Five() } } At(0, 2) }
object { Unit texture { material_map { png "mm_palette.png" interpolate 2 Five() } } At(1, 2) }
object { Unit texture { material_map { png "mm_palette.png" interpolate 3 Five() } } At(2, 2) }
object { Unit texture { material_map { png "mm_rgb.png" Five() } } At(0, 1) }
object { Unit texture { material_map { png "mm_rgb.png" once Flat(<1, 0, 1>) Flat(<0, 1, 1>) Flat(<1, 1, 1>) }
  translate <-0.25, 0, 0> } At(1, 1) }
object { Unit texture { material_map { png "mm_rgb16.png" Five() } } At(2, 1) }
// Once, moved so that a quarter of the panel is off the image; and normalized distance with
// the map turned and scaled, which its textures follow.
object { Unit texture { material_map { png "mm_palette.png" once Five() } translate <0.25, 0.25, 0> }
  At(0, 0) }
object { Unit
  texture {
    material_map { png "mm_palette.png" interpolate 4
      texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
      Five()
    }
    scale 0.5 rotate z*30
  }
  At(1, 0)
}
// Bump maps of the palette's indices, lit from the upper left.
box { <0, 0, 0>, <1, 0.48, 0.1>
  pigment { rgb 1 } finish { ambient 0 diffuse 1 }
  normal { bump_map { png "mm_palette.png" use_index bump_size 0.02 } }
  translate <2.5, 0.1, 0>
}
box { <0, 0, 0>, <1, 0.48, 0.1>
  pigment { rgb 1 } finish { ambient 0 diffuse 1 }
  normal { bump_map { png "mm_palette.png" use_index interpolate 2 bump_size 0.02 } }
  translate <2.5, 0.62, 0>
}
