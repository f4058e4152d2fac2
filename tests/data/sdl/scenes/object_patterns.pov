// The object pattern in a pigment (colours, then pigments), a normal and a texture: a CSG
// difference declared and rotated, a sphere written in the pattern with a transform after it,
// a box moved with the pattern; the first entry outside, the second inside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0, 0> angle 45 }
light_source { <5, 8, -10> color rgb 1 }
#declare Cut = difference { box { -0.8, 0.8 } sphere { <0.9, 0.9, -0.9>, 1 } rotate y*20 }
sphere { <-1.6, 0.3, 0>, 1
  pigment { object { Cut color rgb <0.9, 0.8, 0.2> color rgb <0.1, 0.3, 0.9> } scale 1.1
            translate <-1.6, 0.3, 0> }
  finish { ambient 0.2 diffuse 0.8 }
}
box { <0.4, -0.7, -1>, <2.4, 1.3, 1>
  texture { object { sphere { <0, 0, -1>, 0.9 } scale <1.2, 1, 1> translate <1.4, 0.3, 0>
    texture { pigment { rgb <0.8, 0.2, 0.2> } finish { ambient 0.2 } }
    texture { pigment { rgb <0.2, 0.8, 0.2> } finish { ambient 0.2 phong 0.8 } } } }
}
plane { y, -1
  pigment { object { box { <-1, -2, -1>, <1, 0, 1> } pigment { checker rgb 1 rgb 0.5 scale 0.5 }
            pigment { rgb <0.3, 0.3, 0.8> } } scale <2.3, 2, 1.7> translate <0.05, 0, 0.03> }
  normal { object { Cut normal { bumps 0.3 scale 0.1 } normal { waves 0.5 } } scale 1.5
           translate <0, -1, -2> }
  finish { ambient 0.1 diffuse 0.8 }
}
