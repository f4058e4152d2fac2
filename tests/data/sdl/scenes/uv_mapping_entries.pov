// uv_mapping inside entries of maps and lists of pigments: POV-Ray reads such an entry at the
// intersection's (u, v, 0), placed by its own block's transforms, whatever point its map
// hands it. A pigment_map's entry, a block pattern's listed pigments, an average's entry,
// an entry inside an entry, on a sphere, a box, a torus and a mesh, turned and moved.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -8> right x*image_width/image_height look_at <0, 0.7, 0> }
light_source { <-4, 9, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Fin = finish { ambient 0.3 diffuse 0.7 }
#declare Quad = mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> } face_indices { 2, <0,1,2>, <0,2,3> } }
plane { y, 0 pigment { checker rgb 0.7, rgb 0.5 } finish { Fin } }
sphere { 0, 0.8
  pigment { gradient y pigment_map {
    [0.3 uv_mapping checker rgb <0.9, 0.8, 0.2>, rgb <0.1, 0.2, 0.6> scale <0.0625, 0.125, 1>]
    [0.7 rgb <0.8, 0.2, 0.1>] } scale 0.8 translate -y*0.4 }
  finish { Fin } rotate <20, -40, 0> translate <-2.4, 0.8, 0> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  pigment { checker pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb <0.2, 0.9, 0.4>] }
      scale 0.1 } pigment { rgb <0.9, 0.9, 0.8> } scale 0.5 }
  finish { Fin } rotate y*30 translate <-0.6, 0, -0.8> }
torus { 0.6, 0.25
  pigment { average pigment_map { [1 uv_mapping radial frequency 8 color_map { [0 rgb 1] [1 rgb <0.6, 0.1, 0.6>] }
      rotate x*90 translate <0.5, 0.5, 0>] [1 rgb <0.2, 0.4, 0.9>] } }
  finish { Fin } rotate x*-40 translate <1.2, 0.6, -0.6> }
object { Quad
  pigment { bozo scale 0.3 pigment_map {
    [0.4 gradient x pigment_map { [0 uv_mapping checker rgb 1, rgb 0 scale 0.125] [1 rgb <0.9, 0.5, 0.1>] }]
    [0.6 uv_mapping spiral1 4 color_map { [0 rgb <0.1, 0.5, 0.2>] [1 rgb <0.9, 0.9, 0.3>] } translate <0.5, 0.5, 0>] } }
  finish { Fin } scale 1.6 rotate <-20, 30, 0> translate <1.6, 0.2, 1.2> }
