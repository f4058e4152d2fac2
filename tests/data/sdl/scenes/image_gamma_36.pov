// Image maps of a #version 3.6 scene with assumed_gamma 2.2, as POV-Ray 3.7 reads them
// (make_image_gammas.py): a PNG without colour chunks and a PPM as stored (the working
// gamma decodes them), a PNG with a gAMA chunk or an sRGB chunk by what it says, an image's
// own gamma srgb over it.
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera {
  orthographic
  location <3.31, 1.157, -10>
  right 6.8*x
  up 2.4*y
  look_at <3.31, 1.157, 0>
}
#macro Panel(Column, Row, Image)
  box { <0, 0, 0>, <1, 1, 0.1>
    texture {
      pigment { Image }
      finish { ambient 1 diffuse 0 }
    }
    scale <2, 1, 1>
    translate <Column * 2.3, Row * 1.2, 0>
  }
#end
#declare Image0 = pigment { image_map { png "ig_plain.png" } }
#declare Image1 = pigment { image_map { png "ig_gama18.png" } }
#declare Image2 = pigment { image_map { png "ig_srgb.png" } }
#declare Image3 = pigment { image_map { ppm "ig_ramp.ppm" } }
#declare Image4 = pigment { image_map { png "ig_plain.png" gamma srgb } }
#declare Image5 = pigment { image_map { png "ig_gama18.png" gamma 1.0 } }
Panel(0, 1, Image0)
Panel(1, 1, Image1)
Panel(2, 1, Image2)
Panel(0, 0, Image3)
Panel(1, 0, Image4)
Panel(2, 0, Image5)
