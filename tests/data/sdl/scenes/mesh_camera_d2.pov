// POV-Ray's mesh camera, distribution 2: two meshes side by side across the image (a
// stereo pair, each half the width); POV-Ray takes face row * (width / 2) + column with the
// image's column, so the right half reads its mesh a row on.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = image_width;
#declare H = image_height;
#declare S = 4 / (W / 2);
#declare Half = mesh {
  #for (R, 0, H - 1)
    #for (C, 0, W / 2 - 1)
      #local P = <-2 + C * S, 3 - R * S, 0>;
      triangle { P, P + <0, S, 0>, P + <S, 0, 0> }
    #end
  #end
}
camera {
  mesh_camera {
    1 2
    mesh { Half rotate y * 6 translate <-0.3, -0.4, -6> }
    mesh { Half rotate y * -6 translate <0.3, -0.4, -6> }
  }
}
light_source { <3, 6, -5> color rgb 1 }
background { rgb <0.2, 0.3, 0.45> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <-0.9, -0.3, 0.5>, 0.7 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.6 } }
sphere { <0.8, -0.5, -0.2>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
box { <-0.2, -1, 1.5>, <0.9, 0.6, 2.3> pigment { rgb <0.4, 0.5, 1> } }
