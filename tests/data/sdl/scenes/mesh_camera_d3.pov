// POV-Ray's mesh camera, distribution 3: a coarse mesh of 6 x 4 quads whose uvs span the
// image; each pixel's ray starts where its (u, v) lies on the mesh and, with smooth, leaves
// along the vertex normals interpolated there (a lens fanning the rays out).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#macro N(P) vnormalize(<P.x * 0.35, P.y * 0.35, 1>) #end
#macro U(P) <(P.x + 1.5) / 3, (P.y + 1.1) / 2.2> #end
camera {
  mesh_camera {
    1 3
    mesh {
      #for (I, 0, 5)
        #for (J, 0, 3)
          #local A = <-1.5 + I * 0.5, -1.1 + J * 0.55, 0>;
          #local B = A + <0.5, 0, 0>;
          #local C = A + <0.5, 0.55, 0>;
          #local D = A + <0, 0.55, 0>;
          smooth_triangle { A, N(A), D, N(D), C, N(C) uv_vectors U(A), U(D), U(C) }
          smooth_triangle { A, N(A), C, N(C), B, N(B) uv_vectors U(A), U(C), U(B) }
        #end
      #end
      translate <0, 0, -5>
    }
    smooth
  }
}
light_source { <3, 6, -5> color rgb 1 }
background { rgb <0.2, 0.3, 0.45> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <-0.9, -0.3, 0.5>, 0.7 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.6 } }
sphere { <0.8, -0.5, -0.2>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
box { <-0.2, -1, 1.5>, <0.9, 0.6, 2.3> pigment { rgb <0.4, 0.5, 1> } }
