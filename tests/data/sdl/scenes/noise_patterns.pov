// Noise patterns as POV-Ray's sample scenes use them: marble with turbulence and a colour
// map, wood with its own map turned along y, granite, bozo's default map, leopard and a
// bumps normal on the floor (a box: the horizon of a bumped plane aliases), written as
// textures with transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> right x*image_width/image_height look_at <0, 0.9, 0> }
light_source { <-4, 8, -7> color rgb 1 }
box { <-6, -1, -3>, <6, 0, 5> pigment { rgb 0.6 } normal { bumps 0.4 scale 0.5 } }
sphere { <-2.2, 1, 0>, 0.9
  texture {
    pigment { marble turbulence 0.8 octaves 5
      color_map { [0 rgb <0.95, 0.93, 0.9>] [0.6 rgb <0.6, 0.55, 0.5>] [1 rgb <0.2, 0.15, 0.1>] }
      scale 0.6 }
    finish { phong 0.5 }
  } }
sphere { <0, 1, 0>, 0.9
  pigment { wood turbulence 0.05 color_map { [0, 0.5 color rgb <0.8, 0.5, 0.25> color rgb <0.5, 0.25, 0.1>] [0.5, 1 color rgb <0.5, 0.25, 0.1> color rgb <0.8, 0.5, 0.25>] }
    scale 0.15 rotate x*90 } }
sphere { <2.2, 1, 0>, 0.9 pigment { granite color_map { [0 rgb 0.9] [1 rgb <0.3, 0.2, 0.25>] } scale 2 } }
sphere { <-1.1, 0.4, -1.8>, 0.4 pigment { bozo scale 0.2 } }
sphere { <1.1, 0.4, -1.8>, 0.4 pigment { leopard color_map { [0 rgb <0.9, 0.7, 0.2>] [1 rgb 0.1] } scale 0.08 } normal { wrinkles 0.6 scale 0.2 } }
