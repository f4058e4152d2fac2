// Hand-written POV-Ray 3.7 twin of pov-library.xml (written from POV-Ray's documentation, not
// exported), in the importer's coordinates: Lucent's z is POV-Ray's -z, and POV-Ray's camera
// keeps its usual right vector. The pov: names are the declarations of the include files.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
#include "colors.inc"
#include "textures.inc"
#include "woods.inc"
#include "stones.inc"
#include "golds.inc"

background { rgb <0.4, 0.5, 0.7> }
camera {
  perspective
  location <0, 2.4, -5.5>
  right x * 320 / 240
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-4, 7, -6> color rgb 1 }

plane { y, 0 texture { T_Grnt15 } }
sphere { <-2.1, 0.8, 0>, 0.8 texture { T_Wood10 } }
sphere { <-0.3, 0.8, -0.4>, 0.8 texture { T_Stone9 } }
box { <0.8, 0, -0.3>, <2.2, 1.1, 0.9> texture { T_Gold_1A } }
sphere { <1.5, 1.55, 0.3>, 0.45 pigment { Jade } }
// Lucent's material with a diffuse colour and no ambient: POV-Ray's diffuse 1, ambient 0.
sphere { <0.9, 0.35, -1.3>, 0.35
  pigment { MediumAquamarine }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}
