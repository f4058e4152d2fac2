// POV-Ray's 27 tilings seen from above by an orthographic camera: 9 by 3 panels, tiling N
// on panel N (row by row from the top left), each through a grey map (0 black, 1 white) and
// lit by ambient alone, so each pixel is the tiling's value; the Penrose tilings (25 to 27)
// centred near their panels' middles. The scale and the offsets keep pixel centres off the
// tiles' edges, where a last-bit difference in the hit point could pick either tile.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> right x * 18 up z * 6 }
#declare Grey = color_map { [0 rgb 0] [1 rgb 1] }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 }
box { <-9, -1, 1>, <-7, 0, 3> pigment { tiling 1 color_map { Grey } scale 0.37 translate <-8.0123, 0, 2.0071> } finish { Flat } }
box { <-7, -1, 1>, <-5, 0, 3> pigment { tiling 2 color_map { Grey } scale 0.37 translate <-6.0123, 0, 2.0071> } finish { Flat } }
box { <-5, -1, 1>, <-3, 0, 3> pigment { tiling 3 color_map { Grey } scale 0.37 translate <-4.0123, 0, 2.0071> } finish { Flat } }
box { <-3, -1, 1>, <-1, 0, 3> pigment { tiling 4 color_map { Grey } scale 0.37 translate <-2.0123, 0, 2.0071> } finish { Flat } }
box { <-1, -1, 1>, <1, 0, 3> pigment { tiling 5 color_map { Grey } scale 0.37 translate <0.0123, 0, 2.0071> } finish { Flat } }
box { <1, -1, 1>, <3, 0, 3> pigment { tiling 6 color_map { Grey } scale 0.37 translate <2.0123, 0, 2.0071> } finish { Flat } }
box { <3, -1, 1>, <5, 0, 3> pigment { tiling 7 color_map { Grey } scale 0.37 translate <4.0123, 0, 2.0071> } finish { Flat } }
box { <5, -1, 1>, <7, 0, 3> pigment { tiling 8 color_map { Grey } scale 0.37 translate <6.0123, 0, 2.0071> } finish { Flat } }
box { <7, -1, 1>, <9, 0, 3> pigment { tiling 9 color_map { Grey } scale 0.37 translate <8.0123, 0, 2.0071> } finish { Flat } }
box { <-9, -1, -1>, <-7, 0, 1> pigment { tiling 10 color_map { Grey } scale 0.37 translate <-8.0123, 0, 0.0071> } finish { Flat } }
box { <-7, -1, -1>, <-5, 0, 1> pigment { tiling 11 color_map { Grey } scale 0.37 translate <-6.0123, 0, 0.0071> } finish { Flat } }
box { <-5, -1, -1>, <-3, 0, 1> pigment { tiling 12 color_map { Grey } scale 0.37 translate <-4.0123, 0, 0.0071> } finish { Flat } }
box { <-3, -1, -1>, <-1, 0, 1> pigment { tiling 13 color_map { Grey } scale 0.37 translate <-2.0123, 0, 0.0071> } finish { Flat } }
box { <-1, -1, -1>, <1, 0, 1> pigment { tiling 14 color_map { Grey } scale 0.37 translate <0.0123, 0, 0.0071> } finish { Flat } }
box { <1, -1, -1>, <3, 0, 1> pigment { tiling 15 color_map { Grey } scale 0.37 translate <2.0123, 0, 0.0071> } finish { Flat } }
box { <3, -1, -1>, <5, 0, 1> pigment { tiling 16 color_map { Grey } scale 0.37 translate <4.0123, 0, 0.0071> } finish { Flat } }
box { <5, -1, -1>, <7, 0, 1> pigment { tiling 17 color_map { Grey } scale 0.37 translate <6.0123, 0, 0.0071> } finish { Flat } }
box { <7, -1, -1>, <9, 0, 1> pigment { tiling 18 color_map { Grey } scale 0.37 translate <8.0123, 0, 0.0071> } finish { Flat } }
box { <-9, -1, -3>, <-7, 0, -1> pigment { tiling 19 color_map { Grey } scale 0.37 translate <-8.0123, 0, -2.0071> } finish { Flat } }
box { <-7, -1, -3>, <-5, 0, -1> pigment { tiling 20 color_map { Grey } scale 0.37 translate <-6.0123, 0, -2.0071> } finish { Flat } }
box { <-5, -1, -3>, <-3, 0, -1> pigment { tiling 21 color_map { Grey } scale 0.37 translate <-4.0123, 0, -2.0071> } finish { Flat } }
box { <-3, -1, -3>, <-1, 0, -1> pigment { tiling 22 color_map { Grey } scale 0.37 translate <-2.0123, 0, -2.0071> } finish { Flat } }
box { <-1, -1, -3>, <1, 0, -1> pigment { tiling 23 color_map { Grey } scale 0.37 translate <0.0123, 0, -2.0071> } finish { Flat } }
box { <1, -1, -3>, <3, 0, -1> pigment { tiling 24 color_map { Grey } scale 0.37 translate <2.0123, 0, -2.0071> } finish { Flat } }
box { <3, -1, -3>, <5, 0, -1> pigment { tiling 25 color_map { Grey } scale 0.37 translate <4.0123, 0, -2.0071> } finish { Flat } }
box { <5, -1, -3>, <7, 0, -1> pigment { tiling 26 color_map { Grey } scale 0.37 translate <6.0123, 0, -2.0071> } finish { Flat } }
box { <7, -1, -3>, <9, 0, -1> pigment { tiling 27 color_map { Grey } scale 0.37 translate <8.0123, 0, -2.0071> } finish { Flat } }
