#declare C = rgb 1;
sphere { 0, 1 pigment { rgb 1 } }
light_source { <0, 5, 0> rgb 1 projected_through { C } }
