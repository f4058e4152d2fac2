// assumed_gamma 2.2 as POV-Ray renders it: the colours are used as written and the results
// written decoded from that gamma (Lucent's working-gamma); an image map bilinearly
// interpolated in the working space, an srgb colour encoded into it; a negative spotlight
// that darkens a spot of the floor; a lens of transmit -1 that subtracts what it shows.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera {
  location <0, 3, -7>
  right x*image_width/image_height
  look_at <0, 0.5, 0>
}
light_source { <-4, 8, -6> color rgb 1 }
light_source { <2, 6, -1> color rgb -0.6 spotlight point_at <1.5, 0, 0> radius 8 falloff 14 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } finish { ambient 0.2 diffuse 0.7 } }
box { <-3.2, 0.01, -0.5>, <-1.8, 1.4, 0.5>
  pigment { image_map { png "image_maps.png" once interpolate 2 } translate -0.1*y scale 1.6 translate <-3.2, 0, 0> }
  finish { ambient 0.4 diffuse 0.6 }
}
sphere { <0, 0.8, 0>, 0.8
  pigment { srgb <0.9, 0.5, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.6 }
}
// The lens lies flat over the floor: what it shows is subtracted from its doubled colour.
disc { <2, 0.6, -1>, y, 0.9
  pigment { rgb 0.5 transmit -1 }
  finish { ambient 1 diffuse 0 }
  no_shadow
}
