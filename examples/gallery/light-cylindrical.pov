// Hand-written POV-Ray 3.7 twin of light-cylindrical.xml (written from POV-Ray's behaviour,
// not exported). Lucent's cylindrical light is POV-Ray's cylinder light: parallel light along
// point_at - location, radius and falloff distances from the axis (not angles), the factor
// (1 - rho/falloff)^tightness times the smoothstep between radius and falloff, and no light
// behind the plane through location, where its shadow rays stop too.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, k_a and a specular highlight of the given shininess: pigment k_d, ambient
// k_a / k_d (POV-Ray scales ambient by the pigment), diffuse 1.
#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

background { rgb <0.02, 0.02, 0.03> }
camera {
  perspective
  location <0.5, 4.2, 8>
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
  up y
  angle 58
  look_at <-0.3, 1.6, 0>
}

// color 1 0.9 0.7 times intensity 1.3.
light_source {
  <-1.2, 4, -1.2> color rgb 1.3 * <1, 0.9, 0.7>
  cylinder point_at <0.2, 0, 0.2> radius 1.1 falloff 1.7 tightness 1
}

plane { y, 0 Surface(0.8, 0.06, 0, 64) }
sphere { <0.2, 0.55, 0.4>, 0.55 Surface(<0.2, 0.45, 0.8>, <0.02, 0.05, 0.1>, 0.6, 60) }
box { <-0.9, 0, -0.1>, <-0.7, 1.4, 0.1> Surface(<0.8, 0.7, 0.5>, <0.08, 0.07, 0.05>, 0, 64) }
// The lamp housing, across the beam just behind the plane through the light's location.
cylinder { <-1.2157, 4.0448, -1.2157>, <-1.3568, 4.4481, -1.3568>, 1.9 Surface(0.3, 0.15, 0, 64) }
