// Maps of normals as POV-Ray's sample scenes write them (normmap.pov, slopemap.pov): a
// #default normal that every normal and map entry starts from (its bump_size, then its
// pattern and scale), a normal_map blending marble and scalloped stripes, a checker and a
// hexagon of normals, a brick of normals, slope maps shaping an onion and a gradient, and a
// declared normal with a map placed by the object's transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.3, -9> right x*image_width/image_height look_at <0, 0.3, 0> angle 50 }
light_source { <5, 8, -10> color rgb 1 }
#default { pigment { rgb 0.9 } normal { bump_size 1.2 } finish { phong 0.7 phong_size 120 } }
sphere { <-2.6, 1.6, 0>, 1
  normal { gradient x normal_map { [0.3 marble turbulence 0.5] [0.7 gradient y scallop_wave scale 0.3] }
    translate -x scale 2 } }
sphere { <0, 1.6, 0>, 1
  normal { checker normal { bumps 0.8 scale 0.2 }, normal { wrinkles scale 0.5 } scale 0.7 } }
sphere { <2.6, 1.6, 0>, 1
  normal { hexagon normal { ripples 0.6 } normal { granite 0.3 } normal { leopard scale 0.05 }
    scale 0.3 rotate -90 * x } }
#default { normal { onion 0.8 scale 0.4 } }
sphere { <-2.6, -1, 0>, 1
  normal { slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] } } }
sphere { <0, -1, 0>, 1
  normal { gradient <1, 1, 0> 0.6
    slope_map { [0 <0.5, 1>] [0.25 <1, 0>] [0.5 <0.5, -1>] [0.75 <0, 0>] [1 <0.5, 1>] } } }
#declare Wall = normal { brick normal { granite 0.3 scale 0.3 } normal { bumps 0.6 scale 0.1 }
  brick_size <0.8, 0.3, 0.5> mortar 0.08 }
sphere { 0, 1 normal { Wall } rotate 30 * y translate <2.6, -1, 0> }
