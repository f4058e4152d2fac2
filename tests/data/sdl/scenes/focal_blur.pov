// Focal blur as POV-Ray users write it: a perspective camera focused on the middle ball,
// with every ray taken (variance 0), so both renderers converge to the same blur.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0.5, 1.6, -6>
  look_at <0, 0.8, 0>
  right x*image_width/image_height
  angle 45
  aperture 1.2
  blur_samples 300
  variance 0
  focal_point <0.6, 0.8, 0>
}
light_source { <4, 8, -6> color rgb 1 }
background { color rgb <0.4, 0.6, 0.9> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.15 } finish { ambient 0.2 diffuse 0.8 } }
sphere { <-1.6, 0.6, -2.5>, 0.6 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0.6, 0.8, 0>, 0.8 pigment { color rgb <0.3, 1, 0.3> } finish { phong 0.6 } }
box { <1.6, 0, 4>, <3.4, 2.4, 5> pigment { color rgb <0.3, 0.4, 1> } }
