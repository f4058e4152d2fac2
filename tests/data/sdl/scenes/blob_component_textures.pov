// Blob components with textures of their own (POV-Ray's multi-textured blob): each texture
// shaded whole and weighted by its component's |field| at the hit. A ring of coloured
// spheres crossed by two cylinders, as portfolio/allobjects.pov's blob; a pigment written
// before a component's transform (it moves with the component) and one after (it does
// not); a component with a texture of its layered finish; one without a texture of its own
// (the blob's), a negative one that weighs too; the blob turned as a whole.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -9> right x*image_width/image_height look_at <0, 0.3, 0> angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <4, 3, -6> color rgb 0.4 }
background { rgb <0.15, 0.17, 0.2> }
plane { y, -1.6 pigment { rgb 0.6 } }
blob {
  threshold 0.65
  #declare I = 0;
  #while (I < 6)
    sphere { <1.6, 0, 0>, 0.75, 1 rotate z*60*I
             pigment { rgb <mod(I, 2), I/5, 1 - I/5> } }
    #declare I = I + 1;
  #end
  cylinder { <-2, -2, 0>, <2, 2, 0>, 0.45, 1 pigment { rgb <1, 0, 0> } }
  cylinder { <-2, 2, 0>, <2, -2, 0>, 0.45, 1 }
  sphere { 0, 0.6, -0.5 pigment { rgb <0, 1, 0> } }
  finish { phong 1 phong_size 30 }
  pigment { rgb <0.9, 0.9, 0.8> }
  scale 0.8 rotate y*20 translate <-1.6, 0.4, 0>
}
blob {
  threshold 0.5
  sphere { 0, 1, 1 pigment { checker rgb <1, 0.8, 0.2>, rgb <0.2, 0.3, 0.8> scale 0.25 } translate x*0.5 }
  sphere { 0, 1, 1 translate -x*0.5 pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 1>] } } }
  sphere { 0, 0.8, 1 texture { pigment { rgb <0.2, 0.8, 0.3> } finish { specular 0.6 roughness 0.02 } } scale <1, 2, 1> }
  rotate x*-20 translate <2, 0, 0>
}
