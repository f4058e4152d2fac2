// Height fields from a small grey image (an asymmetric ramp and a peak near the image's
// top-left; a zero border, so that the walls Lucent adds have no height): the image's rows
// land where POV-Ray puts them only if the import mirrors the field in z.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -2.2> right x*4/3 look_at <0, 0, 0.1> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
height_field { pgm "hf_bump.pgm" pigment { rgb <0.4, 0.8, 0.4> }
               translate <-1.05, 0, -0.5> scale <1, 0.5, 1> }
height_field { pgm "hf_bump.pgm" smooth water_level 0.1 pigment { rgb <0.8, 0.6, 0.3> }
               translate <0.05, 0, -0.5> scale <1, 0.5, 1> rotate y*-20 }
