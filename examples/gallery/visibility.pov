// visibility.xml written by hand for POV-Ray 3.7: the same scene with no_image,
// no_reflection, double_illuminate and interior_texture.
// Render: povray +Ivisibility.pov +W320 +H240 -A
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light rgb 1 }
background { rgb <0.3, 0.35, 0.45> }

// Lucent's frame is right-handed: POV-Ray's camera mirrors x to match.
camera {
  perspective
  right -x*320/240
  up y
  angle 55
  location <0, 2.4, 7>
  look_at <0, 0.8, 0>
}

light_source { <3, 6, 5> color rgb 1 }
light_source { <2.45, 1.3, -2.2> color rgb 0.9 }

#declare Matte = finish { ambient 0 diffuse 1 specular 0 phong 0 }
#declare Shiny = finish { ambient 0 diffuse 1 specular 0.4 roughness 1/60 phong 0 }

plane { y, 0 texture { pigment { rgb <0.9, 0.8, 0.55> } finish { Matte } } }

// The mirror.
box {
  <-3.5, 0, -2.3>, <1, 2.6, -2>
  texture { pigment { rgb 0.05 } finish { Matte reflection 0.85 } }
}

// Not seen by the camera; in the mirror and casting its shadow.
sphere {
  <-1.7, 0.7, 0.3>, 0.7
  texture { pigment { rgb <0.85, 0.2, 0.15> } finish { Shiny } }
  no_image
}

// Seen by the camera, not in the mirror.
sphere {
  <-0.3, 0.6, 0.9>, 0.6
  texture { pigment { rgb <0.2, 0.35, 0.9> } finish { Shiny } }
  no_reflection
}

// Two discs facing away from both lights; only the right one is lit from behind.
#declare Paper = texture { pigment { rgb <0.9, 0.9, 0.85> } finish { ambient 0.1 diffuse 1 specular 0 phong 0 } }
disc { <1.9, 1.3, -0.6>, <0, -1, 0.5>, 0.45 texture { Paper } }
disc { <3, 1.3, -0.6>, <0, -1, 0.5>, 0.45 texture { Paper } double_illuminate }

// A ball cut open: its inside shows the interior texture.
sphere {
  0, 0.7
  texture { pigment { rgb <0.3, 0.6, 0.3> } finish { Shiny } }
  interior_texture { pigment { rgb <0.95, 0.75, 0.2> } finish { Matte } }
  clipped_by { plane { y, 0.2 } }
  rotate 25*x
  translate <1.3, 0.75, 1.6>
}
