// uv_mapping on the shapes that have POV-Ray's own (u, v): a checker and an image map
// (image_maps.png, 8 x 4) at (u, v, 0) of a sphere, a box (its cube map), a torus, a lathe
// with a repeated point (a segment without surface that still counts), a sor (its caps'
// v beyond [0, 1]), a bicubic patch; and on a plane and a cylinder, which have none: their
// (u, v) are the world point's x and y. Each shape turned and moved by its own transforms,
// which POV-Ray's (u, v) undo; and an object's uv_mapping before its pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -8> right x*image_width/image_height look_at <0, 0.7, 0> }
light_source { <-4, 9, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Check = pigment { uv_mapping checker rgb <0.9, 0.8, 0.2>, rgb <0.1, 0.2, 0.6>
                           scale <0.125, 0.25, 1> translate z*0.5 }
#declare Img = pigment { uv_mapping image_map { png "image_maps.png" interpolate 2 } }
plane { y, 0 pigment { uv_mapping gradient x color_map { [0 rgb 0.3] [1 rgb 0.8] } scale 3 } }
sphere { 0, 0.8 pigment { Img } finish { phong 0.3 } rotate <20, -40, 0> translate <-2.6, 0.8, 0> }
sphere { 0, 0.5 pigment { Check } rotate x*30 translate <-2.6, 0.5, 1.8> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { Img } rotate y*30 translate <-1, 0, -0.8> }
box { <-0.3, 0, -0.3>, <0.4, 0.8, 0.3> pigment { Check scale 4 } rotate y*-50 translate <0.2, 0, 1.5> }
torus { 0.6, 0.25 pigment { Check } rotate x*-40 translate <1, 0.6, -0.6> }
lathe { linear_spline 5, <0, 0>, <0.5, 0>, <0.5, 0>, <0.3, 0.8>, <0, 1.1>
        pigment { Img } rotate y*20 translate <2.6, 0, 0.3> }
sor { 6, <0.2, -0.2>, <0.45, 0>, <0.3, 0.5>, <0.5, 1>, <0.4, 1.3>, <0.4, 1.5>
      pigment { uv_mapping gradient y color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] }
                scale 2.5 translate -y*1.2 }
      translate <2.8, 0, 2.2> }
bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  <0, 0, 0>, <0.3, 0.4, 0>, <0.7, 0.4, 0>, <1, 0, 0>,
  <0, 0.3, 0.3>, <0.3, 0.7, 0.3>, <0.7, 0.7, 0.3>, <1, 0.3, 0.3>,
  <0, 0.3, 0.7>, <0.3, 0.7, 0.7>, <0.7, 0.7, 0.7>, <1, 0.3, 0.7>,
  <0, 0, 1>, <0.3, 0.4, 1>, <0.7, 0.4, 1>, <1, 0, 1>
  pigment { Img } rotate x*-60 translate <-0.6, 0.9, 2.6> }
cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.35 pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 0.7 }
           translate <1.2, 0, 2.2> }
// An object's uv_mapping: the pigment given after it is read at (u, v, 0), placed by its own
// transforms; the object's later transforms move the ring only.
torus { 0.35, 0.12 rotate x*90 translate <0.3, 0.5, -2.2> uv_mapping
  pigment { checker rgb <1, 1, 1>, rgb <0.8, 0.1, 0.1> scale <0.0625, 0.25, 1> translate z*0.5 }
  rotate y*15 }
