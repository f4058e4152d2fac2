// uv_mapping as POV-Ray reads it: a pigment's (the rest of its block at the mesh's
// uv_vectors, placed by the transforms written in it; the object's later transforms move
// the mesh, not the pattern), a declared uv-mapped pigment continued, a texture's (its
// pigment and a texture_map's entries, all at (u, v, 0)), and a mesh of old triangles,
// some without uv_vectors (POV-Ray's (0, 0) there).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> right x*image_width/image_height look_at <0, 0.8, 0> }
light_source { <-4, 9, -6> color rgb 1 }
#macro Quad(UA, UB, UC, UD)
  mesh2 {
    vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 2, 0>, <-1, 2, 0> }
    uv_vectors { 4, UA, UB, UC, UD }
    face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  }
#end
object { Quad(<0, 0>, <2, 0>, <2, 2>, <0, 2>)
  pigment { uv_mapping spiral2 6 color_map { [0.5 rgb <0.6, 0.1, 0.1>] [0.5 rgb 1] }
    scale 0.5 translate <1, 1, 0> }
  rotate y*20 scale 0.9 translate <-2.2, 0.2, 0.5> }
#declare P = pigment { uv_mapping checker rgb <0.9, 0.8, 0.2>, rgb <0.1, 0.2, 0.6> scale 0.25 translate z*0.5 }
object { Quad(<0, 0>, <1, 0>, <0.8, 1>, <0.2, 1>)
  pigment { P scale 7 } finish { phong 0.5 } rotate y*-15 translate <0, 0.1, 0.8> }
object { Quad(<0, 0>, <1, 0>, <1, 1>, <0, 1>)
  texture { uv_mapping
    gradient <1, 1, 0>
    texture_map {
      [0.3 pigment { rgb <0.1, 0.5, 0.2> } finish { ambient 0.2 }]
      [0.7 pigment { uv_mapping bozo scale 0.1 } ]
    }
    scale 0.5
  }
  rotate y*-30 translate <2.2, 0.2, 0.5> }
mesh {
  triangle { <-3, 0, -4>, <3, 0, -4>, <3, 0, -1> uv_vectors <0, 0>, <3, 0>, <3, 1.5> }
  triangle { <-3, 0, -4>, <3, 0, -1>, <-3, 0, -1> }
  texture { uv_mapping pigment { gradient x color_map { [0 rgb 0.2] [1 rgb <0.9, 0.6, 0.3>] } } }
}
