// A bicubic patch's uv_vectors: the (u, v) of its corners, blended bilinearly at each hit,
// read by uv_mapping (a checker and an image map, image_maps.png, 8 x 4). A twisted set of
// corners on a curved patch, corners that turn and mirror the square on a flat one, and
// the default corners beside them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -6> right x*image_width/image_height look_at <0, 0.4, 0> }
light_source { <-3, 8, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Check = pigment { uv_mapping checker rgb <0.9, 0.8, 0.2>, rgb <0.1, 0.2, 0.6>
                           scale <0.125, 0.25, 1> translate z*0.5 }
#declare Img = pigment { uv_mapping image_map { png "image_maps.png" interpolate 2 } }
#declare Curved = bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  uv_vectors <0.1, 0.2>, <0.9, 0.1>, <0.7, 0.8>, <0.0, 0.6>
  <0, 0, 0>, <0.3, 0.4, 0>, <0.7, 0.4, 0>, <1, 0, 0>,
  <0, 0.3, 0.3>, <0.3, 0.7, 0.3>, <0.7, 0.7, 0.3>, <1, 0.3, 0.3>,
  <0, 0.3, 0.7>, <0.3, 0.7, 0.7>, <0.7, 0.7, 0.7>, <1, 0.3, 0.7>,
  <0, 0, 1>, <0.3, 0.4, 1>, <0.7, 0.4, 1>, <1, 0, 1> }
object { Curved pigment { Check } scale 1.6 rotate x*-50 translate <-2.4, 0.2, 0> }
object { Curved pigment { Img } scale 1.6 rotate x*-50 translate <-0.6, 0.2, 0> }
// Flat, turned and mirrored: u and v swapped, one of them reversed, stretched past 1.
bicubic_patch { type 0 flatness 0.01 u_steps 2 v_steps 2 uv_vectors <0, 2> <0, 0>, <1.5, 0> <1.5, 2>
  <0, 0, 0>, <0, 0.2, 1>, <0, 0.2, 2>, <0, 0, 3>,
  <1, 0, 0>, <1, 0.4, 1>, <1, 0.4, 2>, <1, 0, 3>,
  <2, 0, 0>, <2, 0.4, 1>, <2, 0.4, 2>, <2, 0, 3>,
  <3, 0, 0>, <3, 0.2, 1>, <3, 0.2, 2>, <3, 0, 3>
  pigment { Img } scale 0.6 rotate x*-30 translate <1.2, 0.1, -0.4> }
bicubic_patch { type 1 flatness 0 u_steps 2 v_steps 2
  <0, 0, 0>, <0.3, 0.4, 0>, <0.7, 0.4, 0>, <1, 0, 0>,
  <0, 0.3, 0.3>, <0.3, 0.7, 0.3>, <0.7, 0.7, 0.3>, <1, 0.3, 0.3>,
  <0, 0.3, 0.7>, <0.3, 0.7, 0.7>, <0.7, 0.7, 0.7>, <1, 0.3, 0.7>,
  <0, 0, 1>, <0.3, 0.4, 1>, <0.7, 0.4, 1>, <1, 0, 1>
  pigment { Check } scale 1.2 rotate x*-50 translate <1.0, 0.2, 1.4> }
plane { y, -0.5 pigment { rgb 0.6 } }
