// clip-bowls.xml written by hand for POV-Ray 3.7: the same scene with clipped_by.
// Render: povray +Iclip-bowls.pov +W240 +H180 -A
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light rgb 1 }
background { rgb <0.1, 0.12, 0.16> }

// Lucent's frame is right-handed: POV-Ray's camera mirrors x to match.
camera {
  perspective
  right -x*240/180
  up y
  angle 46
  location <0, 3.4, 5.2>
  look_at <0, 0.5, 0>
}

light_source { <4, 9, 7> color rgb 1 }
light_source { <-6, 5, 2> color rgb 0.35 }

#declare Shiny = finish { ambient 0 diffuse 1 specular 0.4 roughness 1/60 }
#declare Red = texture { pigment { rgb <0.85, 0.2, 0.15> } finish { Shiny } }
#declare Blue = texture { pigment { rgb <0.2, 0.35, 0.9> } finish { Shiny } }
#declare Sand = texture { pigment { rgb <0.9, 0.8, 0.55> } finish { Shiny } }

plane { y, 0 texture { Sand } }

// A bowl: the sphere below y = 0.3 of its own frame, open at the top.
sphere {
  0, 0.9
  texture { Red }
  clipped_by { plane { y, 0.3 } }
  translate <-1.6, 0.9, 0>
}

// A wedge clipped away: kept where x < 0 or y < 0.
sphere {
  0, 0.8
  texture { Blue }
  clipped_by { union { plane { x, 0 } plane { y, 0 } } }
  rotate 30*y
  translate <0.2, 0.8, -0.6>
}

// A slab minus a clipped sphere: the inverted subtrahend keeps its clip, so the slab is
// cut at the clip's plane too, and left open there.
difference {
  box { <-0.8, 0, -0.8>, <0.8, 0.5, 0.8> }
  sphere {
    0, 0.6
    clipped_by { plane { x, 0.2 } }
    translate 0.5*y
  }
  texture { Red }
  rotate -20*y
  translate <1.7, 0, 0.4>
}
