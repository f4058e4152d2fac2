// uv_mapping of normals, bent where POV-Ray 3.7 bends them: a normal's own uv_mapping bends
// the world normal by the pattern's slope at (u, v, 0) (its block's transforms place the
// pattern), whatever the object's transforms; a texture's uv_mapping bends the normal in the
// space of the transforms after the texture; an object's uv_mapping bends the world normal.
// Slope patterns (gradient, leopard, a checker's cells), the normals of their own (bumps,
// wrinkles, ripples, dents) on spheres, boxes, tori and a mesh, turned and moved.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -8> right x*image_width/image_height look_at <0, 0.7, 0> }
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.4> }
#declare Fin = finish { ambient 0.15 diffuse 0.7 phong 0.5 phong_size 30 }
#declare Quad = mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> } face_indices { 2, <0,1,2>, <0,2,3> } }
plane { y, 0 pigment { rgb 0.6 } finish { Fin }
  normal { uv_mapping gradient x 0.6 scale 0.5 } }
// A normal's own uv_mapping, on turned shapes.
sphere { 0, 0.8 pigment { rgb <0.9, 0.7, 0.4> } finish { Fin }
  normal { uv_mapping leopard 1.5 scale 0.05 } rotate <20, -40, 0> translate <-2.6, 0.8, 0> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb <0.5, 0.8, 0.6> } finish { Fin }
  normal { uv_mapping bumps 0.8 scale 0.08 } rotate y*30 translate <-1, 0, -0.8> }
torus { 0.6, 0.25 pigment { rgb <0.6, 0.6, 0.9> } finish { Fin }
  normal { uv_mapping wrinkles 0.7 scale <0.05, 0.1, 1> rotate z*20 } rotate x*-40 translate <1, 0.6, -0.6> }
// A texture's uv_mapping: bent in the space of the transforms after it.
sphere { 0, 0.5
  texture { uv_mapping pigment { checker rgb <0.9, 0.8, 0.2>, rgb <0.1, 0.2, 0.6> scale 0.125 }
    normal { ripples 0.9 scale 0.2 } finish { Fin } }
  rotate x*50 translate <-2.6, 0.5, 1.8> }
object { Quad texture { uv_mapping pigment { rgb <0.8, 0.4, 0.3> } normal { checker 0.8 scale 0.25 }
    finish { Fin } } scale 1.4 rotate <-20, 30, 0> translate <2, 0.3, 1.2> }
// An object's uv_mapping: its textures bent in the world.
box { <-0.3, 0, -0.3>, <0.4, 0.8, 0.3> uv_mapping
  texture { pigment { rgb <0.9, 0.9, 0.8> } normal { dents 1.2 scale 0.1 } finish { Fin } }
  rotate y*-50 translate <0.2, 0, 1.5> }
