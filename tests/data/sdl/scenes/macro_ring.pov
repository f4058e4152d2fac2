// Objects made by a macro in a loop, colours from an array and rand, a reflective floor,
// a spotlight and a gradient sky_sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> right x*4/3 look_at <0, 0.3, 0> }
light_source { <-3, 8, -6> color rgb 1 }
light_source { <4, 6, -2> color rgb <1, 0.9, 0.7> spotlight point_at <0, 0, 0> radius 15 falloff 25 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.8, 0.85, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
#declare Colours = array[3] { <0.9, 0.2, 0.2>, <0.2, 0.8, 0.3>, <0.2, 0.4, 0.9> };
#declare R = seed(7);
#macro Ball(Angle, Index)
  sphere { <2, 0.4 + 0.3*rand(R), 0>, 0.4
    pigment { rgb Colours[mod(Index, 3)] }
    finish { phong 0.7 specular 0.2 }
    rotate y*Angle }
#end
#for (I, 0, 7)
  Ball(I*45, I)
#end
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate y*20 texture { pigment { rgb 0.9 } finish { reflection 0.3 } } }
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } finish { reflection 0.15 } }
