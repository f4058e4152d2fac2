camera { location <0, 1, -5> look_at 0 }
light_source { <0, 5, 0> color rgb 1 area_light x, z, 4, 1 circular }
sphere { 0, 1 pigment { rgb 1 } }
