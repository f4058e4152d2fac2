// A text in POV-Ray's own font (from its include folder), a superellipsoid, a mesh with a
// smooth triangle and a closed mesh2, as POV-Ray reads them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> right x*4/3 look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -8> color rgb 1 }
plane { y, 0 pigment { rgb 0.75 } }
text { ttf "timrom.ttf" "Lucent" 0.3, <0.05, 0, 0> scale 0.9 rotate y*-15
       translate <-2.2, 0.1, 0> pigment { rgb <0.3, 0.5, 0.95> } }
superellipsoid { <0.3, 0.6> scale 0.5 rotate <30, 40, 0> translate <-1.5, 0.6, -1.8>
                 pigment { rgb <0.9, 0.5, 0.9> } }
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0.5> }
  smooth_triangle { <1, 0, 0>, <0, 0, -1>, <1, 1, 0>, <1, 0, -1>, <0, 1, 0.5>, <-1, 1, -1> }
  pigment { rgb <0.3, 0.9, 0.3> } translate <0.3, 0, -1.5>
}
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 0, 1>, <0, 1, 0> }
  face_indices { 4, <0, 1, 2>, <0, 1, 3>, <0, 2, 3>, <1, 2, 3> }
  inside_vector y
  pigment { rgb <0.95, 0.85, 0.3> } rotate y*30 translate <1.8, 0, -1>
}
