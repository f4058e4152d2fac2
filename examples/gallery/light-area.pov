// Hand-written POV-Ray 3.7 twin of light-area.xml (written from POV-Ray's documentation, not
// exported). Lucent's area light (centre, edge vectors u and v, samples nu x nv on a grid
// that includes the edges) is POV-Ray's area_light <u>, <v>, nu, nv. Both average only the
// shadow term and take the light direction from the centre. POV-Ray's recursive averaging
// weighs all samples alike for 2, 4, 8, ... samples per side, so 8 x 8 matches Lucent's plain
// average. shadows="false" is `shadowless` (exact here: no material has a highlight).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d and k_a: pigment k_d, ambient k_a / k_d (POV-Ray scales ambient by the
// pigment), diffuse 1, no highlight.
#macro Matte(Kd, Ka)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular 0 phong 0 reflection 0 }
  }
#end

background { rgb <0.2, 0.2, 0.25> }
camera {
  perspective
  location <0, 4, 7>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.6, 0>
}
light_source { <-1, 5, 1> color rgb 1 area_light <1.5, 0, 0>, <0, 0, 1.5>, 8, 8 }
light_source { <4, 3, 5> color rgb 0.15 shadowless }

plane { y, 0 Matte(0.8, 0.08) }
sphere { <-0.8, 1.6, 0>, 0.5 Matte(<0.8, 0.3, 0.2>, <0.08, 0.03, 0.02>) }
box { <0.5, 0, -1>, <1.5, 1.2, 0> Matte(<0.2, 0.5, 0.8>, <0.02, 0.05, 0.08>) }
cylinder { <-2, 0, -1>, <-2, 0.5, -1>, 0.5 Matte(<0.75, 0.75, 0.3>, 0.07) }
