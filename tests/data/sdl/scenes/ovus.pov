// POV-Ray's ovus: the template's egg (bottom 1, top 0.65), one wider at its top with a
// uv-mapped checker, turned; one of equal radii in a difference that cuts it open; and
// one whose top is twice its bottom or more (POV-Ray's top sphere, with its warning).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -8> right x*image_width/image_height look_at <0, 0.6, 0> angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { rgb 0.6 } }
ovus { 1, 0.65 pigment { rgb <1, 0.9, 0.8> } finish { phong 0.3 } scale 0.8 translate <-2.4, 0.8, 0> }
ovus { 0.6, 1 pigment { uv_mapping checker rgb <0.9, 0.75, 0.2>, rgb <0.15, 0.3, 0.65>
                        scale <0.125, 0.25, 1> translate z*0.5 }
       rotate z*60 rotate y*30 translate <-0.3, 1.2, 0.5> }
difference {
  ovus { 0.7, 0.7 }
  box { <-2, 0.5, -2>, <2, 3, 2> rotate x*-25 }
  pigment { rgb <0.5, 0.8, 0.9> }
  translate <1.6, 0.7, -0.3>
}
ovus { 0.3, 0.7 pigment { rgb <0.8, 0.4, 0.6> } translate <2.9, 0.4, 1.5> }
