// Hand-written POV-Ray 3.7 twin of uv-mapping-shapes.xml (written from POV-Ray's
// documentation, not exported), in POV-Ray's own left-handed numbers: every z of the XML
// negated, rotations about x and y turned the other way (the importer's mapping). Lucent's
// mapping="uv" is POV-Ray's uv_mapping: the pigment is evaluated at the shape's (u, v, 0).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.32, 0.38> }
camera {
  perspective
  location <0, 3.2, -7>
  right x * 320 / 240
  up y
  angle 55
  look_at <0, 0.8, 0>
}
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.35 }

#declare Grid = "textures/uvgrid.png";
#declare Lit = finish { ambient 0.2 diffuse 0.8 specular 0 phong 0 reflection 0 }

plane { y, 0
  pigment { rgb <0.55, 0.55, 0.5> }
  finish { ambient 0.2 diffuse 1 }
}

sphere { 0, 1
  rotate y * 60
  translate <-2.3, 1, -0.3>
  pigment { uv_mapping image_map { png Grid gamma srgb interpolate 2 } }
  finish { Lit }
}

box { <-0.65, 0, -0.65>, <0.65, 1.3, 0.65>
  pigment { uv_mapping image_map { png Grid gamma srgb interpolate 2 } }
  finish { Lit }
  rotate y * -35
  translate <0, 0, -0.6>
}

torus { 0.75, 0.3
  pigment { uv_mapping checker rgb <0.9, 0.75, 0.2>, rgb <0.15, 0.3, 0.65>
            scale <0.125, 0.25, 1> translate z * 0.5 }
  finish { Lit }
  rotate x * -35
  translate <2.3, 0.75, -0.9>
}

lathe { linear_spline 7, <0, 0>, <0.6, 0>, <0.6, 0.15>, <0.35, 0.4>, <0.22, 1.1>, <0.42, 1.2>, <0, 1.45>
  pigment { uv_mapping checker rgb <0.85, 0.2, 0.15>, rgb <0.95, 0.9, 0.8>
            scale <1/6, 0.25, 1> translate z * 0.5 }
  finish { Lit }
  translate <1.3, 0, 1.6>
}

sor { 8, <0.3, -0.2>, <0.45, 0>, <0.7, 0.3>, <0.75, 0.6>, <0.45, 1.1>, <0.3, 1.4>, <0.45, 1.7>, <0.6, 1.8>
  pigment { uv_mapping image_map { png Grid gamma srgb interpolate 2 } }
  finish { Lit }
  translate <-0.9, 0, 1.9>
}
