camera { mesh_camera { 2 0 mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } } } }
sphere { 0, 1 pigment { rgb 1 } }
