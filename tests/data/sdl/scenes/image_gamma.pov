// Image maps decoded as POV-Ray 3.7 decodes them (make_image_gammas.py): a PNG without
// colour chunks from sRGB, one with a gAMA chunk by its gamma, one with an sRGB chunk from
// sRGB, a PPM not at all (its values are working values), and an image's own gamma over
// whatever the file says; under assumed_gamma 1.5, so that each is also encoded.
#version 3.7;
global_settings { assumed_gamma 1.5 }
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
#declare Image4 = pigment { image_map { png "ig_srgb.png" gamma 1.0 } }
#declare Image5 = pigment { image_map { "ig_plain.png" gamma 2.2 } }
Panel(0, 1, Image0)
Panel(1, 1, Image1)
Panel(2, 1, Image2)
Panel(0, 0, Image3)
Panel(1, 0, Image4)
Panel(2, 0, Image5)
