// Filter and transmit that add up to more than 1, as POV-Ray renders them: the surface's
// own terms are scaled by 1 - filter - transmit, below 0, so the surface subtracts its
// colour from what shows through it (advanced/bwstripe.pov's contrast amplifier, transmitfx).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 2.5, -6>
  right x*image_width/image_height
  look_at <0, 0.6, 0>
}
light_source { <-4, 8, -6> color rgb 1 }
background { rgb <0.1, 0.15, 0.2> }
plane { y, 0 pigment { checker rgb <0.9, 0.8, 0.6>, rgb 0.35 } finish { ambient 0.15 diffuse 0.75 } }
// transmit 1.6: what shows through is scaled by 1.6, the sphere's own light by -0.6.
sphere { <-1.6, 0.8, 0>, 0.8
  pigment { rgbt <0.4, 0.3, 0.2, 1.6> }
  finish { ambient 0.2 diffuse 0.6 }
  no_shadow
}
// filter 0.7 and transmit 0.6: the sphere's ambient, diffuse and emission all negative.
sphere { <0.4, 0.8, 0>, 0.8
  pigment { rgbft <0.5, 0.6, 0.9, 0.7, 0.6> }
  finish { ambient 0.3 diffuse 0.5 emission 0.1 }
  no_shadow
}
// A lens of transmit 3 lying over the floor, a contrast amplifier.
disc { <2.1, 0.3, -0.8>, y, 0.8
  pigment { rgbt <0.5, 0.5, 0.5, 3> }
  finish { ambient 1 diffuse 0 }
  no_shadow
}
