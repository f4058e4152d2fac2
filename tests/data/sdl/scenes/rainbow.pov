// Rainbows against POV-Ray 3.7: one partly transparent (filter and transmit in its colour
// map), faded by the distance to a wall, on an arc with a falloff; a second, whole and
// opaque, overlapping it (the two averaged); a glass ball, inside which no rainbow is
// drawn (it is not hollow); and a fog after them.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -1> look_at <0, 4, 10> angle 100 }
background { rgb <0.3, 0.5, 0.8> }
light_source { <0, 20, -10> rgb 1 }
plane { y, -1 pigment { rgb 0.6 } finish { ambient 0.2 diffuse 0.6 } }
box { <2, -1, 29>, <12, 6, 30> pigment { rgb <0.8, 0.7, 0.6> } finish { ambient 1 diffuse 0 } }
sphere { <-3, 2, 8>, 1.2 pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 }
         interior { ior 1.3 } }
rainbow {
  direction <0.1, -0.2, 1> angle 35 width 8 distance 40 arc_angle 160 falloff_angle 100
  color_map {
    [0 rgbf <1, 0.4, 1, 1>]
    [0.3 rgbf <0.2, 0.2, 1, 0.7>]
    [0.6 rgbt <0.2, 1, 0.2, 0.3>]
    [1 rgb <1, 0.2, 0.2>]
  }
}
rainbow {
  direction <0.1, -0.2, 1> angle 48 width 4
  color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 1, 1>] }
}
fog { distance 400 color rgbt <0.9, 0.9, 1, 0.7> }
