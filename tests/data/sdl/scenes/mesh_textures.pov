// Meshes whose triangles have textures of their own: a mesh2's texture_list indexed by its
// faces (some faces without an index take the mesh's texture), a mesh's triangles naming
// declared textures (texture_list of one texture three times is that texture), a patterned
// texture that moves with the mesh, and a mesh2 with uv_mapping after its faces (PoseRay's
// output), whose textures are read at the faces' (u, v).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -6> look_at <0, 0.4, 0> angle 45 }
light_source { <-3, 6, -5> rgb 1 }
light_source { <4, 3, -2> rgb 0.4 shadowless }
background { rgb 0.2 }
#declare Red = texture { pigment { rgb <1, 0.1, 0.1> } finish { phong 0.5 } }
#declare Checks = texture { pigment { checker rgb <0.1, 0.2, 1> rgb 1 scale 0.25 } }
#declare UvChecks = texture { uv_mapping pigment { checker rgb <1, 0.6, 0> rgb 0.1 scale 0.25 } }
// A pyramid of four faces: two red, one checked, one of the mesh's own green.
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.2, 0> }
  texture_list { 2, texture { Red } texture { Checks } }
  face_indices { 4, <0, 1, 4>, 0, <1, 2, 4>, 1, <2, 3, 4>, 0, 0, 0, <3, 0, 4> }
  texture { pigment { rgb <0.2, 1, 0.2> } }
  rotate y * -25
  scale 0.9
  translate <-1.6, 0, 0>
}
// Triangles with declared textures and one smooth triangle without (the mesh's yellow).
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> texture { Red } }
  triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> texture_list { Checks, Checks, Checks } }
  smooth_triangle { <0, 0, 0>, <-1, 0, -0.2>, <0, 1, 0>, <-1, 0.3, 0>, <0, 0, 1>, <-1, 0, 0.3> }
  texture { pigment { rgb <1, 1, 0> } }
  rotate y * -30
  translate <0.2, 0, 0>
}
// A square of two faces with uvs; uv_mapping after the faces reads both textures at (u, v).
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  uv_vectors { 4, <0, 0>, <2, 0>, <2, 2>, <0, 2> }
  texture_list { 2, texture { pigment { checker rgb <1, 0.6, 0> rgb 0.1 scale 0.25 } } texture { UvChecks } }
  face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 1 }
  uv_mapping
  scale 1.3
  rotate y * 25
  translate <1.5, 0, 0>
}
plane { y, 0 pigment { rgb 0.7 } }
