// Hand-written POV-Ray 3.7 twin of image-palette-entries.xml (written from POV-Ray's
// documentation, not exported). Lucent's <palette index="N" filter="F" transmit="T"> is
// POV-Ray's image_map `filter N, F` and `transmit N, T`; its image's transmit is `transmit all`.
// Images decoded from sRGB as Lucent's.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.25, 0.3, 0.4> }
camera {
  perspective
  location <0, 1.6, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 1, 0>
}
light_source { <-3, 6, 6> color rgb 1 }
light_source { <3, 3, 5> color rgb 0.3 }

#declare Emblem = "textures/emblem_opaque.png";
#declare Lit = finish { ambient 0.3 diffuse 0.7 specular 0 phong 0 reflection 0 }
#macro Quad(A, B, C, D) mesh { triangle { A, B, C } triangle { A, C, D } #end

Quad(<-5, -1, -1.5>, <5, -1, -1.5>, <5, 4, -1.5>, <-5, 4, -1.5>)
  pigment { checker rgb <0.9, 0.85, 0.75>, rgb <0.2, 0.25, 0.3> scale 0.4 }
  finish { Lit }
}
// Left: the background clear, the star a coloured filter.
Quad(<-3.2, 0.2, 0>, <-1.2, 0.2, 0>, <-1.2, 2.2, 0>, <-3.2, 2.2, 0>)
  pigment { image_map { png Emblem gamma srgb transmit 0, 1 filter 8, 0.75 filter 9, 0.75 filter 10, 0.75 filter 11, 0.75 filter 12, 0.75 filter 13, 0.75 filter 14, 0.75 filter 15, 0.75 }
    scale 2 translate <-3.2, 0.2, 0> }
  finish { Lit }
}
// Middle: every entry transmitting 0.3 (transmit all), the background clear.
sphere { <0, 1.1, 0>, 0.9
  pigment { image_map { png Emblem gamma srgb map_type 1 interpolate 2 transmit all 0.3 transmit 0, 1 }
    rotate y*-90 translate <0, 1.1, 0> }
  finish { ambient 0.3 diffuse 0.7 specular 0 phong 0.4 phong_size 30 reflection 0 }
}
// Right: the ring filtering, read bilinearly; the background half clear.
Quad(<1.2, 0.2, 0>, <3.2, 0.2, 0>, <3.2, 2.2, 0>, <1.2, 2.2, 0>)
  pigment { image_map { png Emblem gamma srgb interpolate 2 transmit 0, 0.5 filter 1, 0.8 filter 2, 0.8 filter 3, 0.8 filter 4, 0.8 filter 5, 0.8 filter 6, 0.8 filter 7, 0.8 }
    scale 2 translate <1.2, 0.2, 0> }
  finish { Lit }
}
