// Image maps inside maps of pigments and block patterns' pigment lists (image_maps.png,
// 8 x 4): each entry's image placed by its own transforms after the map's, with its own
// map_type, once (clear off the image), interpolate and filter/transmit all, blended as
// any entry of a pigment_map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> right x*image_width/image_height look_at <0, 0.6, 0> }
light_source { <-4, 9, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
// A floor: a gradient whose entries are the image (planar, laid flat, twice as large) and
// a plain colour, blended between 0.3 and 0.7.
plane { y, 0
  pigment { gradient x
    pigment_map {
      [0.3 image_map { png "image_maps.png" interpolate 2 } rotate x*90 scale 2]
      [0.7 rgb <0.8, 0.7, 0.5>]
    }
    scale 4 }
  finish { ambient 0.3 diffuse 0.7 }
}
// A checker of two images: spherical on the odd cells, planar once (clear off the image, a
// see-through white, over a red box inside) with transmit all 0.3 on the even.
sphere { <-2, 0.9, 0>, 0.9
  pigment { checker
    pigment { image_map { png "image_maps.png" map_type 1 interpolate 4 } }
    pigment { image_map { png "image_maps.png" once transmit all 0.3 } scale 0.6 translate <0.1, 0.2, 0> }
    scale 0.5 }
  finish { ambient 0.3 diffuse 0.7 }
}
box { <-2.4, 0.5, -0.4>, <-1.6, 1.3, 0.4> pigment { rgb <0.8, 0.1, 0.1> } }
// A box whose bozo map holds a cylindrical image and a filtered planar one.
box { <-0.8, 0, -0.8>, <0.8, 1.4, 0.8>
  pigment { bozo
    pigment_map {
      [0.4 image_map { png "image_maps.png" map_type 2 interpolate 3 } scale <1, 0.7, 1>]
      [0.6 image_map { png "image_maps.png" filter all 0.4 } rotate z*30]
    }
    scale 0.4 }
  finish { ambient 0.3 diffuse 0.7 }
  rotate y*25
}
// A hexagon of an image, a colour and a torus-mapped image.
box { <1.4, 0, -0.7>, <2.8, 1.4, 0.7>
  pigment { hexagon
    pigment { image_map { png "image_maps.png" } scale 0.3 }
    pigment { rgb <0.2, 0.6, 0.3> }
    pigment { image_map { png "image_maps.png" map_type 5 interpolate 2 } }
    rotate x*-90 scale 0.35 }
  finish { ambient 0.3 diffuse 0.7 }
}
