camera { mesh_camera { 1 0 mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } } smooth } }
sphere { 0, 1 pigment { rgb 1 } }
