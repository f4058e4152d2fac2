// Hand-written POV-Ray 3.7 twin of image-map-entries.xml (written from POV-Ray's
// documentation, not exported). Lucent's <image projection="P"> entry of a <pigment-map> or
// <pigment-list> is POV-Ray's image_map with map_type P as a pigment_map entry's body or a
// block pattern's pigment, placed by the transforms written after it.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.2, 0.3, 0.4> }
camera {
  perspective
  location <0, 3, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 55
  look_at <0, 0.6, 0>
}
light_source { <-4, 9, 6> color rgb 1 }

#declare Grid = "textures/uvgrid.png";
#declare Lit = finish { ambient 0.3 diffuse 0.7 specular 0 phong 0 reflection 0 }

plane { y, 0
  pigment { gradient x
    pigment_map {
      [0.3 image_map { png Grid gamma srgb interpolate 2 } scale 0.5 rotate x*90]
      [0.7 rgb <0.8, 0.7, 0.5>]
    }
    scale 4 }
  finish { Lit }
}

sphere { <-2, 0.9, 0>, 0.9
  pigment { checker
    pigment { image_map { png Grid gamma srgb map_type 1 interpolate 4 } }
    pigment { image_map { png Grid gamma srgb once interpolate 2 transmit all 0.3 } scale 0.6 translate <0.1, 0.2, 0> }
    scale 0.5 }
  finish { Lit }
}
box { <-2.4, 0.5, -0.4>, <-1.6, 1.3, 0.4>
  pigment { rgb <0.8, 0.1, 0.1> }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}

box { <-0.8, 0, -0.8>, <0.8, 1.4, 0.8>
  pigment { onion
    pigment_map {
      [0.4 image_map { png Grid gamma srgb map_type 2 interpolate 3 } scale <1, 0.7, 1>]
      [0.6 image_map { png Grid gamma srgb interpolate 2 filter all 0.4 } rotate z*30]
    }
    scale 0.4 }
  finish { Lit }
  rotate y*-25
}

box { <1.4, 0, -0.7>, <2.8, 1.4, 0.7>
  pigment { hexagon
    pigment { image_map { png Grid gamma srgb } scale 0.3 }
    pigment { rgb <0.2, 0.6, 0.3> }
    pigment { image_map { png Grid gamma srgb map_type 5 interpolate 2 } }
    rotate x*-90 scale 0.35 }
  finish { Lit }
}
