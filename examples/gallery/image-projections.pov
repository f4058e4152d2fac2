// Hand-written POV-Ray 3.7 twin of image-projections.xml (written from POV-Ray's
// documentation, not exported). Lucent's <image projection="P"> is POV-Ray's image_map with
// map_type 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus); its transform is the
// pigment's; once, interpolate (none, bilinear 2, bicubic 3, normalized 4) and transmit
// (transmit all) are POV-Ray's. The image is decoded from sRGB as Lucent decodes it.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

#declare Grid = "textures/uvgrid.png";

background { rgb <0.25, 0.3, 0.4> }
camera {
  perspective
  location <0, 2.8, 8.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 52
  look_at <0.1, 0.7, 0>
}
light_source { <-4, 8, 6> color rgb 1 }
light_source { <5, 3, 4> color rgb 0.3 }

// Lucent's ambient a and diffuse d with a texture: both multiplied by the pigment.
#macro Surface(A, D, P)
  finish { ambient A diffuse D phong P specular 0 reflection 0 }
#end

plane { y, 0
  pigment {
    image_map { png Grid gamma srgb interpolate 2 transmit all 0.5 }
    scale 1.5 rotate x * 90
  }
  Surface(0.25, 0.75, 0)
}
plane { y, -0.4
  pigment { checker rgb <0.8, 0.6, 0.3>, rgb 0.1 scale 0.5 }
  Surface(0.2, 0.8, 0)
}
box { <-3.3, 0.01, -0.5>, <-1.9, 1.41, 0.5>
  pigment {
    image_map { png Grid gamma srgb once interpolate 2 }
    scale 1.2 translate <-3.2, 0.1, 0>
  }
  Surface(0.3, 0.7, 0)
}
sphere { <-0.7, 0.85, 0>, 0.85
  pigment {
    image_map { png Grid gamma srgb map_type 1 interpolate 3 }
    rotate y * 40 translate <-0.7, 0.85, 0>
  }
  Surface(0.25, 0.75, 0.4)
}
cylinder { <1.1, 0.01, 0>, <1.1, 1.8, 0>, 0.55 open
  pigment {
    image_map { png Grid gamma srgb map_type 2 interpolate 4 once }
    scale <1, 1.4, 1> translate <1.1, 0.01, 0>
  }
  Surface(0.25, 0.75, 0)
}
torus { 1, 0.3
  pigment { image_map { png Grid gamma srgb map_type 5 } }
  Surface(0.25, 0.75, 0)
  scale 0.6 rotate x * -60 translate <2.7, 0.8, 0.3>
}
