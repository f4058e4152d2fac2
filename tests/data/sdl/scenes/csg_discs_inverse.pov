// Discs inverted in CSG and clips, as POV-Ray keeps them: a sphere cut by an inverse disc
// (kept above the plane), a box minus a union of a disc and a box (POV-Ray inverts the
// union into an intersection of its parts inverted, so the inner box's surface, below the
// disc's plane, vanishes and the box is cut at the plane), a sphere clipped by an inverse
// disc, and a cylinder cut by a scaled and turned disc.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 3, -6> right x*image_width/image_height look_at <0, 0, 0> }
light_source { <5, 8, -5> color rgb 1 }
plane { y, -1.2 pigment { checker rgb 1 rgb 0.4 } }
intersection {
  sphere { 0, 1 }
  disc { 0, y, 0.9 inverse }
  pigment { rgb <1, 0.5, 0.3> }
  translate x*-2.2
}
difference {
  box { -0.8, 0.8 }
  union { disc { <0, 0.3, 0>, y, 0.5 } box { <0.2, -1, -1>, <1, -0.2, 1> } }
  pigment { rgb <0.3, 0.9, 0.5> }
  rotate y*30
}
sphere { 0, 0.8 clipped_by { disc { 0, z, 1 inverse } } pigment { rgb <0.5, 0.6, 1> } translate x*2.2 }
intersection {
  cylinder { -y, y, 0.6 }
  disc { 0, <1, 1, 0>, 0.7 scale <1, 2, 1> rotate z*20 }
  pigment { rgb 1 }
  translate <0.5, 0, -2>
}
