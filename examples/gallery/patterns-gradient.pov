// Hand-written POV-Ray 3.7 twin of patterns-gradient.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type wave frequency phase> is the POV-Ray
// pigment pattern of that name with the wave keyword (sine_wave, triangle_wave, scallop_wave,
// ramp_wave, cubic_wave, poly_wave e) and the frequency and phase modifiers; the pattern's
// transform is written inside the pigment, the sphere's after the texture, so that the pattern
// moves with the sphere (Lucent's object space). A material with a pattern has diffuse 1 and
// its single-number ambient multiplies the pattern's colour, as POV-Ray's ambient does.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 5, 10>
  right -x * 400 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 46
  look_at <0, 0.4, 0.2>
}
light_source { <-5, 9, 7> color rgb 1 }
light_source { <6, 4, 6> color rgb 0.3 }

// The spheres' finish: Lucent's defaults (no specular) with phong 0.5 and its size 40.
#declare Shiny = finish { ambient 0.1 diffuse 1 brilliance 1 specular 0 phong 0.5 phong_size 40 reflection 0 }

plane {
  y, 0
  texture {
    pigment {
      gradient x
      triangle_wave
      color_map { [0 rgb <0.85, 0.82, 0.75>] [1 rgb <0.35, 0.35, 0.4>] }
      scale 1.5
    }
    finish { ambient 0.1 diffuse 0.8 brilliance 1 specular 0 phong 0 reflection 0 }
  }
}

// Back row.
sphere {
  0, 0.65
  texture {
    pigment { gradient y sine_wave frequency 3 color_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <1, 0.85, 0.3>] } }
    finish { Shiny }
  }
  translate <-3.4, 0.65, -0.8>
}
sphere {
  0, 0.65
  texture {
    pigment {
      onion triangle_wave
      color_map { [0 rgb <0.1, 0.3, 0.8>] [1 rgb <0.85, 0.9, 1>] }
      scale 0.4
      translate <0.3, 0.5, 0.6>
    }
    finish { Shiny }
  }
  translate <-1.7, 0.65, -0.8>
}
sphere {
  0, 0.65
  texture {
    pigment { radial scallop_wave frequency 8 color_map { [0 rgb <0.15, 0.5, 0.15>] [1 rgb <0.9, 0.95, 0.5>] } }
    finish { Shiny }
  }
  translate <0, 0.65, -0.8>
}
sphere {
  0, 0.65
  texture {
    pigment {
      spiral1 3 ramp_wave
      color_map { [0 rgb <0.5, 0.1, 0.6>] [0.5 rgb <1, 0.6, 0.8>] [1 rgb <0.5, 0.1, 0.6>] }
      rotate -25 * x
    }
    finish { Shiny }
  }
  translate <1.7, 0.65, -0.8>
}
sphere {
  0, 0.65
  texture {
    pigment {
      spiral2 2 cubic_wave
      color_map { [0 rgb <0.05, 0.4, 0.45>] [1 rgb <0.95, 0.85, 0.6>] }
      rotate -25 * x
    }
    finish { Shiny }
  }
  translate <3.4, 0.65, -0.8>
}

// Front row.
sphere {
  0, 0.7
  texture {
    pigment {
      leopard poly_wave 0.5
      color_map { [0 rgb <0.95, 0.75, 0.3>] [0.45 rgb <0.9, 0.65, 0.25>] [0.75 rgb <0.15, 0.08, 0.03>] }
      scale 0.09
    }
    finish { Shiny }
  }
  translate <-2.4, 0.7, 1.3>
}
sphere {
  0, 0.7
  texture {
    pigment { wood phase 0.3 color_map { [0 rgb <0.88, 0.6, 0.3>] [1 rgb <0.45, 0.25, 0.1>] } scale 0.15 }
    finish { Shiny }
  }
  translate <0, 0.7, 1.3>
}
sphere {
  0, 0.7
  texture {
    pigment {
      marble frequency 2 sine_wave
      color_map { [0 rgb <0.92, 0.9, 0.85>] [0.7 rgb <0.6, 0.6, 0.65>] [1 rgb <0.15, 0.15, 0.2>] }
      scale 0.5
    }
    finish { Shiny }
  }
  translate <2.4, 0.7, 1.3>
}
