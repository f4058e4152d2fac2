// Tilings as normals (POV-Ray's slope of the tiling's value, four samples): tiling 7 and the
// Penrose kites and darts (26), on two panels lit from the side, seen from above.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> right x * 8 up z * 4 }
light_source { <-5, 10, 3> color rgb 1 }
box { <-4, -1, -2>, <0, 0, 2> pigment { rgb 0.8 } normal { tiling 7 0.6 scale 0.57 translate <0.013, 0, 0.021> } finish { ambient 0 diffuse 1 } }
box { <0, -1, -2>, <4, 0, 2> pigment { rgb 0.8 } normal { tiling 26 0.8 scale 0.53 translate <2.013, 0, 0.021> } finish { ambient 0 diffuse 1 } }
