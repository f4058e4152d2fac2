#version 3.7;
sphere { 0, 1 interior_texture { pigment { rgb 1 } } }
