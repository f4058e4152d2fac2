// POV-Ray's mesh camera, distribution 1: the faces of two meshes counted on from one to
// the next (the top half of the image, then the bottom), the faces turned away from the
// scene and the rays reversed (direction z below 0), no hit beyond 7.5 units (max
// distance: the background there).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = image_width;
#declare H = image_height;
#declare S = 4 / W;
#macro Rows(From, To)
  mesh2 {
    vertex_vectors {
      (To - From) * W * 3,
      #for (R, From, To - 1)
        #for (C, 0, W - 1)
          #local P = <-2 + C * S, 1.5 - R * S, 0>;
          P, P + <S, 0, 0>, P + <0, S, 0>,
        #end
      #end
    }
    face_indices {
      (To - From) * W,
      #for (K, 0, (To - From) * W - 1) <3 * K, 3 * K + 1, 3 * K + 2>, #end
    }
    translate <0, 0, -6>
  }
#end
// Declared: POV-Ray 3.7 reads a mesh2 written out in a mesh_camera as a mesh.
#declare Top = Rows(0, H / 2)
#declare Bottom = Rows(H / 2, H)
camera {
  mesh_camera {
    3 1 7.5
    mesh2 { Top }
    mesh { Bottom }
  }
  direction <0, 0, -1>
}
light_source { <3, 6, -5> color rgb 1 }
background { rgb <0.2, 0.3, 0.45> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <-0.9, -0.3, 0.5>, 0.7 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.6 } }
sphere { <0.8, -0.5, -0.2>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
box { <-0.2, -1, 1.5>, <0.9, 0.6, 2.3> pigment { rgb <0.4, 0.5, 1> } }
