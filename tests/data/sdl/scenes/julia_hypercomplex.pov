// Hypercomplex julia fractals: z² + c (POV-Ray's fractal2 and fractal4 parameters) and its
// cube, which POV-Ray iterates as z² with another step, shadowed on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> right x*4/3 look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1.5 pigment { rgb 0.6 } }
julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr max_iteration 7 precision 20
  pigment { rgb <0.8, 0.65, 0.85> } finish { phong 0.7 } scale 0.8 rotate <83, 0, -70> translate <-1.3, 0.3, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex cube max_iteration 9 precision 20
  pigment { rgb <0.9, 0.5, 0.6> } scale <0.6, 0.9, 0.6> rotate <135, -30, 0> translate <1.5, 0, 0> }
