// CSG with discs, as POV-Ray keeps it: a disc's inside is the half-space below its plane
// (its surface covers only the disc), so an operation keeps the other operands cut by that
// half-space and the disc's surface where the others say. A sphere cut by a tilted disc
// (intersection), a sphere minus a disc with a hole, a box merged with two discs (the box
// gone below the discs' planes), a disc first in a difference (the sphere's surface shows
// below the disc), a capped sphere minus a box (a rewritten operation as an operand), a
// union of a sphere and a disc in an intersection, an inverse difference in an
// intersection, solids clipped by a disc and by a union of a disc and a box, and one
// clipped by a polygon (inside nowhere: nothing is left). A glass lens, a sphere cut by a
// disc that covers the cut (its flat face a closed wall: the lens refracts as a solid). Where POV-Ray links an
// intersection or difference to the frame, its box (its operands' boxes met, a
// difference's first operand's; a disc's box is 0.002 thick) bounds what rays see of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 4, -7> right x*image_width/image_height look_at <0, -0.2, 0> angle 56 }
light_source { <5, 10, -8> color rgb 1 }
light_source { <-6, 3, -2> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -1.5 pigment { checker rgb 1 rgb 0.5 } }
intersection {
  sphere { 0, 0.8 }
  disc { <0, 0.2, 0>, <0.3, 1, 0>, 1.5 }
  pigment { rgb <1, 0.3, 0.2> }
  translate <-3.6, 0, 1.6>
}
difference {
  sphere { 0, 0.8 }
  disc { <0, -0.2, 0>, y, 0.7, 0.3 }
  pigment { rgb <0.9, 0.6, 1> }
  translate <3.4, 0, 1.4>
}
difference {
  intersection { sphere { 0, 1 } disc { <0, 0.3, 0>, y, 2 } }
  box { <0, -2, -2>, <2, 0, 0> }
  pigment { rgb <1, 0.5, 0.2> }
  translate <-2.2, 0, 0>
}
difference {
  disc { 0, <0.2, 1, -0.3>, 1.2, 0.2 }
  sphere { 0, 0.7 }
  pigment { rgb <0.3, 0.9, 0.4> }
}
merge {
  box { -0.5, 0.5 }
  disc { <0, 0.2, 0>, y, 0.9 }
  disc { <0.1, 0, 0>, x, 0.7 }
  pigment { rgb <0.4, 0.5, 1> }
  translate <2.2, 0, 0>
}
intersection {
  union { sphere { <0, 0.3, 0>, 0.6 } disc { <0, -0.2, 0>, -y, 2 } }
  cylinder { <0, -1.4, 0>, <0, 1, 0>, 0.5 }
  pigment { rgb <1, 1, 0.4> }
  translate <-1, 0, -2>
}
sphere {
  0, 0.6
  clipped_by { disc { <0, 0.1, 0>, <0, 1, 0.4>, 1 } }
  pigment { rgb <1, 0.3, 0.8> }
  translate <1.2, -0.6, -2>
}
sphere {
  0, 0.6
  clipped_by { union { disc { <0, 0.3, 0>, -y, 1 } box { <-1, -1, -1>, <0, 0, 0> } } }
  pigment { rgb <0.3, 1, 1> }
  translate <2.6, -0.6, -1.5>
}
sphere {
  0, 0.5
  clipped_by { polygon { 4, <-1, 0>, <1, 0>, <0, 1>, <-1, 0> } }
  pigment { rgb 1 }
  translate <0, 1, -2>
}
intersection {
  box { -0.6, 0.6 }
  difference { sphere { 0, 0.7 } disc { 0, y, 1 } inverse }
  pigment { rgb 0.8 }
  rotate x*-30
  translate <-2.6, -0.7, -1.9>
}
intersection {
  sphere { <0, -0.5, 0>, 1 }
  disc { 0, -y, 1.01 }
  material {
    texture { pigment { color rgbf <0.8, 1, 0.95, 0.9> } finish { ambient 0.1 diffuse 0.1 reflection 0.1 specular 0.8 roughness 0.003 } }
    interior { ior 1.5 }
  }
  translate <0.2, -1.3, -2.9>
}
