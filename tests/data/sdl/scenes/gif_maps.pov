// GIFs (make_gif_maps.py) where POV-Ray reads images: palette images of four colours, their
// colours sRGB-decoded under 3.7 in image maps, named by the gif keyword or by their
// extension; one whose graphic control extension makes blue transparent, over a yellow wall
// (plain, with bilinear interpolation, with `filter all`, with an entry's own transmit); a
// material map and a height field, which take the palette indices; a bump map by index and an
// image pattern of the transparency; a POT file's height field (16-bit heights in a GIF).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1.6, 1.6, -4.6> look_at <1.6, 1.6, 0> angle 52 }
light_source { <-2, 6, -6> rgb 1 }
background { rgb 0.2 }
box { <-0.5, -0.5, 0.5>, <3.8, 2.8, 0.6> pigment { rgb <1, 0.9, 0.1> } }
#declare Square = box { <0, 0, 0>, <1, 1, 0.01> }
object { Square pigment { image_map { gif "gif_plain.gif" } } translate <-0.1, 0, 0> }
object { Square pigment { image_map { "gif_transparent.gif" } } translate <1.05, 0, 0> }
object { Square pigment { image_map { gif "gif_transparent" interpolate 2 } } translate <2.2, 0, 0> }
object { Square pigment { image_map { gif "gif_plain" filter all 0.6 } } translate <-0.1, 1.1, 0> }
object { Square pigment { image_map { gif "gif_plain" transmit 3, 0.7 interpolate 2 } }
  translate <1.05, 1.1, 0> }
object { Square
  texture { material_map { gif "gif_plain"
    texture { pigment { rgb <1, 0.5, 0> } }
    texture { pigment { checker rgb 1 rgb 0 scale 0.05 } }
    texture { pigment { rgb <0.5, 0, 1> } }
    texture { pigment { rgb <0, 1, 1> } } } }
  translate <2.2, 1.1, 0> }
object { Square pigment { rgb 0.8 } normal { bump_map { gif "gif_plain" use_index bump_size 0.02 } }
  translate <-0.1, 2.2, 0> }
object { Square
  pigment { image_pattern { gif "gif_transparent" use_alpha } color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } }
  translate <1.05, 2.2, 0> }
// Heights of index x 256 / 65535: up to 0.0117, shaded by a gradient that does not wrap.
height_field { gif "gif_plain"
  pigment { gradient y color_map { [0 rgb <0, 0.3, 0>] [1 rgb 1] } scale 0.016 translate y * -0.002 }
  scale <1, 15, 1> rotate x * -60 translate <2.2, 2.2, -0.3> }
// Heights up to 0xB0FF / 65535 from the left half's high bytes and the right half's low ones.
height_field { pot "gif_heights.pot"
  pigment { gradient y color_map { [0 rgb <0.4, 0, 0>] [1 rgb <1, 0.8, 0.8>] } scale 0.7 }
  scale <0.4, 0.6, 1> rotate x * -60 translate <3.38, 1.1, -0.3> }
