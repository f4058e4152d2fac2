// CSG, #declare'd objects placed by object { }, #default, a texture written between
// transforms, the simple shapes, and two lights (one shadowless).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
#default { finish { ambient 0.15 diffuse 0.7 } }
background { rgb <0.1, 0.12, 0.2> }
camera { location <2, 3, -6> right x*4/3 look_at <0, 0.5, 0> angle 55 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 5, -2> color rgb <0.3, 0.3, 0.4> shadowless }
#declare Post = cylinder { 0, y*1.5, 0.2 pigment { rgb <0.2, 0.5, 0.9> } }
#declare I = 0;
difference {
  box { <-1, 0, -1>, <1, 1, 1> }
  sphere { <0, 1, 0>, 0.8 }
  pigment { rgb <0.9, 0.8, 0.3> }
  rotate y*25
}
#while (I < 2)
  object { Post translate <-2 + 4*I, 0, 1> }
  #declare I = I + 1;
#end
cone { <0, 0, 0>, 0.5, <0, 1, 0>, 0 scale 0.8 pigment { rgb <0.3, 0.8, 0.3> } translate <1.5, 0, -1.5> }
torus { 0.6, 0.15 rotate x*30 translate <-1.3, 0.4, -1.6> pigment { rgb <0.8, 0.3, 0.6> } }
union {
  sphere { <0, 0.3, 0>, 0.3 }
  sphere { <0.5, 0.3, 0>, 0.3 pigment { rgb <1, 1, 1> } }
  pigment { rgb <0.9, 0.4, 0.1> }
  translate <0.2, 0, -2.2>
}
plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }
