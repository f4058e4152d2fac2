camera { mesh_camera { 1 0 } }
sphere { 0, 1 pigment { rgb 1 } }
