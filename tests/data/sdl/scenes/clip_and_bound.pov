// clipped_by and bounded_by as POV-Ray applies them, held to POV-Ray's image by
// tests/sdl/scene_image_test.cpp: a clip written before and after transforms, a clipped
// subtrahend (which keeps its clip), bounds linked with a clip, a top-level sphere whose
// bounds POV-Ray drops but whose box it keeps, a CSG operand and an unbounded quartic
// cut by their bounds.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 9, -6> rgb 1 }
background { rgb <0.1, 0.12, 0.16> }
#default { finish { ambient 0.1 diffuse 0.8 specular 0.3 roughness 0.02 } }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.6> } }

// A bowl: the clip is written after the translate, in the world, and moves with the
// later rotate.
sphere { 0, 0.8 pigment { rgb <0.9, 0.3, 0.2> }
  translate <-2.2, 0.8, 0>
  clipped_by { plane { y, 1.1 } }
  rotate 10*z
}

// A slab minus a clipped sphere: POV-Ray's inverted subtrahend keeps its clip.
difference {
  box { <-0.8, 0, -0.8>, <0.8, 0.6, 0.8> }
  sphere { <0, 0.6, 0>, 0.6 clipped_by { plane { x, 0.1 } } }
  pigment { rgb <0.3, 0.5, 0.9> }
  rotate -25*y translate <0, 0, 1.5>
}

// Bounds linked with the clip: a hemisphere.
sphere { 0, 0.7 bounded_by { box { <-1, 0, -1>, <1, 1, 1> } } clipped_by { bounded_by }
  pigment { rgb <0.3, 0.8, 0.4> } translate <2.2, 0.2, 0.3> }

// A sphere bounded by a smaller box: POV-Ray drops the bounds but takes their box as the
// sphere's, so rays that miss the box miss the sphere. (Its shadow is left out: POV-Ray
// cuts the shadow rays by that box only in part, docs/povray-import.md.)
sphere { 0, 0.7 bounded_by { box { <-0.4, -0.5, -0.5>, <0.4, 0.5, 0.5> } }
  pigment { rgb <0.9, 0.8, 0.2> } translate <-0.9, 0.7, -1.8> no_shadow }

// A union whose operand is bounded by a small sphere: the operand is searched only along
// the rays that meet it.
union {
  sphere { 0, 0.6 bounded_by { sphere { <0, 0.5, 0>, 0.3 } } }
  cylinder { <0, 0, 0>, <0, 0.2, 0>, 0.8 }
  pigment { rgb <0.8, 0.4, 0.8> } translate <1.1, 0.6, -1.9>
}
