// tiles: POV-Ray's old checker of textures (the first on the odd cells, tile2's on the
// even ones), its textures layered and finished each their own way, moved by the texture's
// and the object's transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> right x*image_width/image_height look_at <0, 0.8, 0> }
light_source { <-4, 9, -6> color rgb 1 }
plane { y, 0
  texture { tiles {
    texture { pigment { rgb <0.9, 0.85, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
    texture { pigment { gradient x color_map { [0 rgbt <0.6, 0.1, 0.1, 0>] [0.5 rgbt <0, 0, 0, 1>] } scale 0.5 } }
    tile2
    texture { pigment { rgb <0.1, 0.2, 0.4> } finish { phong 0.8 reflection 0.2 } }
  } scale 0.8 rotate y*20 }
}
sphere { <0, 1, 0>, 1
  texture { tiles { texture { pigment { rgb <1, 0.8, 0.1> } } tile2 texture { pigment { bozo scale 0.2 } } } scale 0.4 }
  rotate y*30 translate x*0.3 }
