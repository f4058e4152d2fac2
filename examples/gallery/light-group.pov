// light-group.xml written by hand for POV-Ray 3.7: the same scene with two light_groups.
// Render: povray +Ilight-group.pov +W320 +H240 -A
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light rgb 1 }
background { rgb <0.25, 0.3, 0.4> }

// Lucent's frame is right-handed: POV-Ray's camera mirrors x to match.
camera {
  perspective
  right -x*320/240
  up y
  angle 50
  location <0, 3, 8>
  look_at <0, 0.8, 0>
}

light_source { <1, 8, 4> color rgb <0.9, 0.9, 0.85> }

#declare White = texture {
  pigment { rgb 0.9 }
  finish { ambient 0.05/0.9 diffuse 1 specular 0.5 roughness 1/40 phong 0 }
}

plane { y, 0 texture { pigment { rgb <0.8, 0.8, 0.75> } finish { ambient 0 diffuse 1 } } }

// Lit by its blue light alone; it still shadows the white light on the floor.
light_group {
  light_source { <-4, 3, 3> color rgb <0.3, 0.5, 1> }
  sphere { <0, 1, 0>, 1 texture { White } }
  box { <-0.6, 0, 1.2>, <0.6, 0.5, 1.8> texture { White } }
  translate -1.8*x
}

// Lit by the white light and its red one, which the post shadows.
light_group {
  light_source { <6, 2, 2> color rgb <1, 0.3, 0.2> }
  sphere { <1.8, 1, 0>, 1 texture { White } }
  global_lights on
}

box {
  <3.3, 0, 0.6>, <3.5, 2.5, 0.8>
  texture { pigment { rgb <0.6, 0.55, 0.4> } finish { ambient 0 diffuse 1 } }
}
