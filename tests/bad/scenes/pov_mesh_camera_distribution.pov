camera { mesh_camera { 1 4 mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } } } }
sphere { 0, 1 pigment { rgb 1 } }
