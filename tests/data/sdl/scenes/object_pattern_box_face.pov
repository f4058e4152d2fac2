// The object pattern on a box's face: a floor at y = 0 coloured by a box standing on it (from
// y = 0 up) takes the inside colour where it lies in the box's bottom face, as POV-Ray's box
// counts its faces inside (Box::Inside); a CSG difference of boxes, whose faces inside the
// first box are inside it too. Seen straight down, so both renderers' hit points lie exactly
// in the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 5, 0> look_at 0 right x*4 up z*3 }
light_source { <-3, 8, -5> color rgb 1 }
background { rgb 0.1 }
plane { y, 0
  pigment { object { box { <-1.6, 0, -0.6>, <-0.2, 1, 0.6> } rgb <0.9, 0.3, 0.1> rgb <0.1, 0.3, 0.9> } }
  finish { ambient 0.5 diffuse 0.5 } clipped_by { plane { x, 0 } } }
plane { y, 0
  pigment { object { difference { box { <0.2, 0, -1>, <1.8, 1, 1> } box { <0.6, -1, -0.4>, <1.4, 0, 0.4> } }
    rgb <0.9, 0.8, 0.2> rgb <0.2, 0.7, 0.3> } }
  finish { ambient 0.5 diffuse 0.5 } clipped_by { plane { x, 0 inverse } } }
