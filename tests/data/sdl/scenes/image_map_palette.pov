// Palette entries with their own filter and transmit (image_map's `filter N, F` and
// `transmit N, F`) on a 6 x 4 palette image of 16 entries (mm_palette.png,
// make_material_maps.py), in front of a checker: entries of their own alone, with each
// interpolation but bicubic (their filter and transmit blended as the colours are; with
// bicubic, whose weights overshoot, a few pixels differ by up to 6/255, not yet matched), `all`
// given after an entry (which it overwrites) and before one (which keeps its own), and once.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  orthographic
  location <1.8, 1.2, -5>
  look_at <1.8, 1.2, 0>
  right x*3.6
  up y*2.4
}
light_source { <-3, 6, -8> color rgb 1 }
background { rgb <0.1, 0.15, 0.2> }
plane { z, 0.5 pigment { checker rgb <0.9, 0.8, 0.2>, rgb <0.1, 0.3, 0.8> scale 0.15 }
  finish { ambient 0.5 diffuse 0.5 } }
#declare Panel = box { <0, 0, 0>, <1, 1, 0.05> }
#macro At(Col, Row) translate <0.1 + 1.2*Col, 0.1 + 1.2*Row, 0> #end
#declare Fin = finish { ambient 0.6 diffuse 0.4 }
object { Panel pigment { image_map { png "mm_palette.png"
  filter 3, 0.8 transmit 5, 0.6 filter 7, 0.5 transmit 7, 0.3 filter 11, 1 transmit 14, 1 } }
  finish { Fin } At(0, 1) }
object { Panel pigment { image_map { png "mm_palette.png" interpolate 2
  filter 3, 0.8 transmit 5, 0.6 filter 7, 0.5 transmit 7, 0.3 filter 11, 1 transmit 14, 1 } }
  finish { Fin } At(1, 1) }
object { Panel pigment { image_map { png "mm_palette.png" interpolate 4
  filter 0, 0.9 transmit 1, 0.9 filter 2, 0.4 transmit 2, 0.4 filter 8, 1 } }
  finish { Fin } At(2, 1) }
object { Panel pigment { image_map { png "mm_palette.png"
  filter 3, 0.8 transmit 5, 0.6 filter all 0.3 } }
  finish { Fin } At(0, 0) }
object { Panel pigment { image_map { png "mm_palette.png"
  transmit all 0.4 transmit 2, 0.6 filter 9, 0.5 transmit 12, 0 } }
  finish { Fin } At(1, 0) }
object { Panel pigment { image_map { png "mm_palette.png" once interpolate 2
  filter 4, 0.7 transmit 10, 0.7 } scale 0.8 translate <0.1, 0.1, 0> }
  finish { Fin } At(2, 0) }
