// POV-Ray's mesh camera, distribution 0: two screens of one face per pixel, rows top
// first, the second moved half a pixel (each sample the mean of its two rays), every ray
// started 0.5 along its face's normal (location z).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = image_width;
#declare H = image_height;
#declare S = 4 / W;
#declare Screen = mesh {
  #for (R, 0, H - 1)
    #for (C, 0, W - 1)
      #local P = <-2 + C * S, 1.5 - R * S, 0>;
      triangle { P, P + <0, S, 0>, P + <S, 0, 0> }
    #end
  #end
}
camera {
  mesh_camera {
    2 0
    mesh { Screen rotate x * 12 rotate y * 8 translate <0, 1, -6> }
    mesh { Screen translate <S / 2, -S / 2, 0> rotate x * 12 rotate y * 8 translate <0, 1, -6> }
  }
  location <0, 0, 0.5>
}
light_source { <3, 6, -5> color rgb 1 }
background { rgb <0.2, 0.3, 0.45> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <-0.9, -0.3, 0.5>, 0.7 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.6 } }
sphere { <0.8, -0.5, -0.2>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
box { <-0.2, -1, 1.5>, <0.9, 0.6, 2.3> pigment { rgb <0.4, 0.5, 1> } }
