// Hand-written POV-Ray 3.7 twin of light-area-spot.xml (written from POV-Ray's documentation,
// not exported). The stage lamp is a macro of a union: a no_shadow housing and an
// area_light with spotlight pointing down its own -y, both moved by the union's transform.
// POV-Ray takes a spot-shaped area light's cone from its centre (radius = Lucent's inner,
// falloff = angle, tightness 0 for Lucent's smoothstep edge) and its area axes turn with the
// union, as Lucent places a <light> in its <use>'s frame. 8 x 8 samples without jitter are
// Lucent's plain grid average.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.04 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, k_a and a specular highlight of the given shininess: pigment k_d, ambient
// k_a / k_d (POV-Ray scales ambient by the pigment), diffuse 1.
#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

#macro StageLamp(Colour)
  union {
    cylinder { <0, 0.05, 0>, <0, 0.35, 0>, 0.3 Surface(0.2, 0.3, 0.5, 60) no_shadow }
    light_source {
      <0, 0, 0>
      color rgb Colour
      spotlight
      point_at <0, -1, 0>
      radius 6
      falloff 15
      tightness 0
      area_light <0.6, 0, 0>, <0, 0, 0.6>, 8, 8
    }
  }
#end

background { rgb <0.02, 0.02, 0.03> }
camera {
  perspective
  location <0, 4, 7.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.6, 0>
}

// POV-Ray's rotate matrices are Lucent's (coordinates are kept as they are).
object { StageLamp(<1, 0.8, 0.55>) rotate z * 32 translate <-3.4, 4.2, 0.4> }
object { StageLamp(<0.55, 0.75, 1>) rotate x * -8 rotate z * -33 translate <3.6, 3.8, -1> }

plane { y, 0 Surface(0.8, 1, 0, 1) }
sphere { <-0.7, 0.7, 0>, 0.7 Surface(<0.85, 0.35, 0.2>, <1, 0.4, 0.25>, 0.5, 60) }
box { <0.4, 0, -0.9>, <1.3, 1.1, 0> Surface(<0.25, 0.5, 0.85>, <0.3, 0.5, 1>, 0.3, 40) rotate y * 25 }
cylinder { <0.2, 0, 1.2>, <0.2, 0.5, 1.2>, 0.35 Surface(<0.8, 0.8, 0.3>, <1, 1, 0.4>, 0, 1) }
