// Fog seen through the gap of a clipped sphere (textures/interior_texture.pov's second
// sphere): a camera ray that comes in through the gap never entered the sphere, so POV-Ray
// fogs it up to the inner side it meets; a glass sphere beside it, entered through its
// surface, is not fogged inside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <100, 50, 50> right x*image_width/image_height angle 58 look_at <-5, 25, 0> }
plane { y, 0 pigment { rgb 1 } }
sphere { <0, 25, 30>, 25
  texture { pigment { rgb <0.5, 0.4, 1> } }
  interior_texture { pigment { rgb <1, 0.7, 0> } }
  clipped_by { box { <-50, 20, -50>, <50, 35, 50> inverse } }
}
sphere { <0, 25, -30>, 20
  pigment { rgbf <1, 1, 1, 0.9> }
  interior { ior 1 }
}
light_source { <400, 5000, 3000> rgb 1.5 }
fog { rgb 1 distance 170 }
