// Focal blur without a focal point: POV-Ray then focuses at |direction| from the location
// (here 6.5, on the yellow ball); blur_samples gives a minimum as well as a maximum.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 3, -6>
  direction <0, 0, 6.5>
  right x*4*image_width/image_height
  up y*4
  look_at <0, 0.5, 0>
  aperture 1.5
  blur_samples 64, 300
  confidence 0.5
  variance 0
}
light_source { <4, 8, -6> color rgb 1 }
background { color rgb <0.4, 0.6, 0.9> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.15 scale 0.5 } finish { ambient 0.2 diffuse 0.8 } }
sphere { <0, 0.5, 0>, 0.5 pigment { color rgb <1, 0.8, 0.2> } finish { phong 0.6 } }
sphere { <-1.2, 0.4, -2.5>, 0.4 pigment { color rgb <1, 0.3, 0.2> } }
cylinder { <1.2, 0, 3>, <1.2, 2, 3>, 0.4 pigment { color rgb <0.3, 0.4, 1> } }
