// Quaternion julia fractals as POV-Ray users write them: z² + c turned, z³ + c on a tilted
// slice, and z² + c scaled unevenly; the shapes are mirrored in z by the import.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5.5> right x*4/3 look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1.3 pigment { rgb 0.6 } }
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <0.9, 0.6, 0.2> } finish { phong 0.6 } rotate y*30 translate <-1.7, 0, 0> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion cube max_iteration 8 precision 20
  slice <0.2, 0, 0.3, 1>, 0.1
  pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.6 } rotate x*-20 translate <0.6, 0, 0.5> }
julia_fractal { <-0.2, 0.6, 0.2, 0> max_iteration 6 precision 30
  pigment { rgb <0.5, 0.9, 0.4> } scale <0.8, 1, 1.2> translate <2, 0.2, 1.5> }
