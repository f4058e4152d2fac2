// Hand-written POV-Ray 3.7 twin of normal-facets.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent facets normal is POV-Ray's facets with the
// same size, coords and metric (keep-facing-away: POV-Ray keeps a bent normal that faces
// away). A material's diffuse colour is the pigment with diffuse 1, its single-number
// ambient divided by the pigment (POV-Ray scales ambient by it).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.15, 0.2, 0.3> }
camera {
  perspective
  location <0, 2.2, 9>
  right -x * 320 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 45
  look_at <0, 1.2, 0>
}
light_source { <-4, 8, 9> color rgb 1 }
light_source { <5, 3, 7> color rgb 0.3 }

#macro Faceted(Kd, N)
  texture {
    pigment { rgb Kd }
    normal { N }
    finish { ambient rgb 0.15 / Kd diffuse 1 phong 0.6 phong_size 40 specular 0 reflection 0 }
  }
#end

// Left: the default facets (size 0.1, the normal's direction snapped).
#declare Gem = normal { facets }
sphere { <-2.6, 1.2, 0>, 1.1 Faceted(<0.8, 0.8, 0.9>, Gem) }
// Middle: larger facets, their random points found with metric 3.
#declare Large = normal { facets size 0.3 metric 3 }
sphere { <0, 1.2, 0>, 1.1 Faceted(<0.9, 0.6, 0.3>, Large) }
// Right: cells laid out by the point, tilted by half the noise gradient.
#declare Cells = normal { facets size 0.2 coords 0.5 }
sphere { <2.6, 1.2, 0>, 1.1 Faceted(<0.4, 0.7, 0.5>, Cells) }

plane {
  y, 0
  texture {
    pigment { rgb <0.5, 0.5, 0.55> }
    finish { ambient rgb <0.1 / 0.5, 0.1 / 0.5, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}
