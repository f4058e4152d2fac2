// Pavements as pigments and as normals (POV-Ray's slope of the pavement's value, four
// samples): squares in tiles of five with rounded inner corners through a grey map, hexagons
// in tiles of four and triangles in tiles of six with cut outer corners as normals, lit from
// the side, seen from above; each panel's offset keeps pixel centres off the cells' edges.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> right x * 12 up z * 4 }
light_source { <-5, 10, 3> color rgb 1 }
box { <-6, -1, -2>, <-2, 0, 2> pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 8
      interior 2 scale 0.57 translate <0.013, 0, 0.021> color_map { [0 rgb 0.9] [1 rgb 0.1] } }
      finish { ambient 1 diffuse 0 } }
box { <-2, -1, -2>, <2, 0, 2> pigment { rgb 0.8 } normal { pavement 0.6 number_of_sides 6
      number_of_tiles 4 pattern 5 scale 0.31 translate <0.013, 0, 0.021> } finish { ambient 0 diffuse 1 } }
box { <2, -1, -2>, <6, 0, 2> pigment { rgb 0.8 } normal { pavement 0.8 number_of_sides 3
      number_of_tiles 6 pattern 7 exterior 1 form 2 scale 0.43 translate <2.013, 0, 0.021> }
      finish { ambient 0 diffuse 1 } }
