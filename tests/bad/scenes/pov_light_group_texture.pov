#version 3.7;
light_group { light_source { <0, 5, 0> rgb 1 } sphere { 0, 1 } pigment { rgb 1 } }
