// Image maps projected as POV-Ray projects them, on an 8 x 4 image (image_maps.png): planar
// once on a box's face and repeated with transmit all on the floor, spherical on a sphere,
// cylindrical on an open cylinder, torus on a torus; each interpolation. Bump maps projected
// spherical and planar (once).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 2.5, -7>
  right x*image_width/image_height
  look_at <0, 0.6, 0>
}
light_source { <-4, 8, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
// The floor: the image repeated, half see-through, over a checker lower down.
plane { y, 0
  pigment { image_map { png "image_maps.png" transmit all 0.5 } rotate x*90 scale 1.5 }
  finish { ambient 0.3 diffuse 0.7 }
}
plane { y, -0.5 pigment { checker rgb 0.9, rgb 0.2 } }
// Planar, once, bilinear: the image on [0,1]² of the face, clear beyond it.
box { <-3.2, 0.01, -0.5>, <-1.8, 1.4, 0.5>
  pigment { image_map { png "image_maps.png" once interpolate 2 } translate <-0.2, -0.1, 0> scale 1.4 translate <-3.2, 0, 0> }
  finish { ambient 0.4 diffuse 0.6 }
}
// Spherical, normalized distance.
sphere { <-0.8, 0.8, 0>, 0.8
  pigment { image_map { png "image_maps.png" map_type 1 interpolate 4 } rotate y*30 }
  finish { ambient 0.3 diffuse 0.7 phong 0.4 }
  translate 0
}
// Cylindrical, bicubic, once: clear above and below y in [0, 1] of its space.
cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.6 open
  pigment { image_map { png "image_maps.png" map_type 2 interpolate 3 once } translate y*0.2 scale <1, 1.2, 1> }
  finish { ambient 0.3 diffuse 0.7 }
  translate <1, 0.01, 0>
}
// Torus, no interpolation.
torus { 1, 0.3
  pigment { image_map { png "image_maps.png" map_type 5 } }
  finish { ambient 0.3 diffuse 0.7 }
  scale 0.6 rotate x*-60 translate <2.6, 0.8, 0.2>
}
// A projected bump map (spherical, bilinear) on a sphere turned about x.
sphere { <-2.2, 2.2, 1.5>, 0.6
  pigment { rgb <0.9, 0.85, 0.8> }
  normal { bump_map { png "image_maps.png" map_type 1 interpolate 2 bump_size 4 } rotate x*30 }
  finish { ambient 0.2 diffuse 0.8 phong 0.5 }
}
// Planar and once: bent on the image's square only.
box { <1.6, 1.6, 1>, <3, 2.6, 1.2>
  pigment { rgb 0.8 }
  normal { bump_map { png "image_maps.png" once bump_size -3 } scale <0.8, 0.6, 1> translate <1.8, 1.8, 0> }
  finish { ambient 0.2 diffuse 0.8 phong 0.5 }
}
