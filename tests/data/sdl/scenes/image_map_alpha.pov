// Image maps with transparency, as POV-Ray 3.7 reads it: an RGBA PNG's alpha channel is
// each pixel's transmit 1 - alpha (transmit all adds to it); a palette PNG's tRNS alphas
// likewise, except that transmit N, T sets an entry's transmit, and transmit all, on a
// palette image, every entry's (in place of the alphas); filter all gives every entry a
// filter. Blended as the colours are. A checker behind shows through.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.5, 0.5, -5> look_at <2.5, 0.5, 0> right x*5 up y*1 }
background { color rgb <1, 0.2, 0.1> }
plane { z, 1 pigment { checker color rgb <0.1, 0.3, 0.9> color rgb <0.9, 0.9, 0.2> scale 0.125 }
  finish { ambient 1 diffuse 0 } }
#declare Flat = finish { ambient 1 diffuse 0 }
box { <0, 0, 0>, <1, 1, 0.001>
  pigment { image_map { png "image_pattern_rgba8.png" interpolate 2 } } finish { Flat } }
box { <1, 0, 0>, <2, 1, 0.001>
  pigment { image_map { png "image_pattern_rgba8.png" transmit all 0.25 } translate x } finish { Flat } }
box { <2, 0, 0>, <3, 1, 0.001>
  pigment { image_map { png "alpha_palette.png" transmit 0, 0.5 } translate x*2 } finish { Flat } }
box { <3, 0, 0>, <4, 1, 0.001>
  pigment { image_map { png "alpha_palette.png" filter all 0.3 interpolate 2 } translate x*3 } finish { Flat } }
box { <4, 0, 0>, <5, 1, 0.001>
  pigment { image_map { png "alpha_palette.png" transmit all 0.3 transmit 2, 0.75 interpolate 2 }
    translate x*4 } finish { Flat } }
