// Textures where POV-Ray places them: a checker floor turned by rotate, a texture written
// between an object's transforms (it follows only the later ones), a union's texture
// given to its operands (moved by the union's later transforms, not the operands' own),
// a declared object moved by object { }, and the block patterns' colour lists.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> right x*image_width/image_height look_at <0, 0.8, 0> }
light_source { <-4, 9, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.85, 0.7>, rgb <0.2, 0.3, 0.4> scale 0.75 rotate y*30 } }
sphere { 0, 1 scale <0.6, 1, 0.6>
  pigment { gradient x color_map { [0 rgb <1, 0.2, 0.1>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <1, 0.2, 0.1>] } scale 0.5 }
  rotate z*30 translate <-2.2, 1, 0> }
union {
  sphere { <-0.5, 0, 0>, 0.45 scale <1, 2, 1> }
  sphere { <0.5, 0, 0>, 0.45 translate y*0.2 }
  pigment { onion color_map { [0 rgb <0.1, 0.6, 0.2>] [0.5, 1 color rgb 1 color rgb <0.1, 0.2, 0.8>] } scale 0.3 }
  scale 1.2 rotate y*-20 translate <0, 1, 0.5>
}
#declare Ball = sphere { 0, 0.6 pigment { hexagon rgb <0.9, 0.1, 0.1>, rgb 1, rgb <0.1, 0.1, 0.9> scale 0.15 rotate x*90 } }
object { Ball scale 1.3 translate <2.1, 0.8, 0> }
box { <-0.6, 0, -0.6>, <0.6, 0.5, 0.6>
  pigment { brick rgb 0.8, rgb <0.7, 0.25, 0.1> brick_size <0.3, 0.1, 0.15> mortar 0.02 }
  rotate y*45 translate <-1.2, 0, -1.8> }
