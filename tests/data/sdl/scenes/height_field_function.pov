// Height fields from functions: a scalar function whose y runs against the field's z (the
// field's far edge takes y = 0: the slope up the x axis and the ridge along y show it), and a
// pigment function's grey (agate, a noise pattern, with global_settings' noise generator).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.4, -2.0> right x*4/3 look_at <0, 0, 0.1> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
height_field {
  function 40, 30 { 0.1 + 0.5*y*y + 0.25*sin(7*x)*(1 - y) }
  smooth
  pigment { rgb <0.4, 0.8, 0.4> }
  translate <-1.05, 0, -0.5> scale <1, 0.6, 1>
}
height_field {
  function 64, 64 { pigment { agate color_map { [0 rgb 0] [0.3 rgb 0.2] [0.7 rgb 0.8] [1 rgb 1] } scale 0.6 } }
  water_level 0.1
  pigment { rgb <0.8, 0.6, 0.3> }
  translate <0.05, 0, -0.5> scale <1, 0.4, 1> rotate y*-20
}
