// Hand-written POV-Ray 3.7 twin of patterns-turbulence.xml (written from POV-Ray 3.7's
// documentation, not exported). Lucent's turbulence, octaves, omega and lambda are POV-Ray's
// pigment modifiers of those names; the turbulence is written before the pattern's own
// transform, so it works in pattern space and scales with the pattern, as in Lucent. The
// sphere's translation comes after the texture, so each pattern is centred on its sphere.
// A material with a pattern has diffuse 1 and its single-number ambient multiplies the
// pattern's colour, as POV-Ray's ambient does.
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

#declare Base = finish { ambient 0.1 diffuse 1 brilliance 1 specular 0 reflection 0 }

plane {
  y, 0
  texture {
    pigment {
      bozo turbulence 0.8 octaves 4
      color_map { [0 rgb <0.75, 0.72, 0.65>] [1 rgb <0.45, 0.48, 0.5>] }
      scale 1.5
    }
    finish { Base diffuse 0.8 phong 0 }
  }
}

// Back row.
sphere {
  0, 0.7
  texture {
    pigment {
      wood turbulence <0.05, 0.05, 0.4> octaves 4
      color_map { [0 rgb <0.9, 0.62, 0.32>] [0.7 rgb <0.75, 0.48, 0.24>] [1 rgb <0.4, 0.2, 0.08>] }
      scale <0.12, 0.12, 1>
      rotate 70 * y
    }
    finish { Base phong 0.4 phong_size 40 }
  }
  translate <-3.3, 0.7, -0.8>
}
sphere {
  0, 0.7
  texture {
    pigment {
      marble turbulence 1.2 octaves 3
      color_map { [0 rgb <0.92, 0.92, 0.9>] [0.75 rgb <0.7, 0.7, 0.72>] [0.9 rgb <0.3, 0.3, 0.35>] [1 rgb <0.1, 0.1, 0.12>] }
      scale 0.7
    }
    finish { Base phong 0.6 phong_size 80 }
  }
  translate <-1.1, 0.7, -0.8>
}
sphere {
  0, 0.7
  texture {
    pigment {
      agate
      color_map { [0 rgb <0.1, 0.05, 0.02>] [0.45 rgb <0.9, 0.7, 0.55>] [0.6 rgb <0.9, 0.65, 0.35>] [1 rgb <0.6, 0.3, 0.12>] }
      scale 0.6
    }
    finish { Base phong 0.6 phong_size 80 }
  }
  translate <1.1, 0.7, -0.8>
}
sphere {
  0, 0.7
  texture {
    pigment {
      granite turbulence 0.3 octaves 5
      color_map { [0.2 rgb <0.1, 0.1, 0.12>] [0.35 rgb <0.6, 0.45, 0.4>] [0.6 rgb <0.85, 0.8, 0.75>] [0.8 rgb <0.5, 0.5, 0.55>] }
      scale 0.6
    }
    finish { Base phong 0.4 phong_size 40 }
  }
  translate <3.3, 0.7, -0.8>
}

// Front row.
sphere {
  0, 0.7
  texture {
    pigment {
      bozo turbulence 0.6 octaves 6 omega 0.7
      color_map { [0 rgb <0.2, 0.35, 0.85>] [0.5 rgb <0.55, 0.65, 0.95>] [0.65 rgb 1] [1 rgb 0.95] }
      scale 0.4
    }
    finish { Base phong 0.4 phong_size 40 }
  }
  translate <-2.4, 0.7, 1.3>
}
sphere {
  0, 0.7
  texture {
    pigment {
      spotted turbulence 0.5 lambda 3
      color_map { [0 rgb <0.15, 0.5, 0.15>] [0.6 rgb <0.7, 0.85, 0.3>] [1 rgb <0.95, 0.95, 0.6>] }
      scale 0.3
    }
    finish { Base phong 0.4 phong_size 40 }
  }
  translate <0, 0.7, 1.3>
}
sphere {
  0, 0.7
  texture {
    pigment {
      crackle turbulence 0.2
      color_map { [0 rgb <0.15, 0.05, 0.02>] [0.05 rgb <0.8, 0.35, 0.1>] [1 rgb <0.95, 0.8, 0.4>] }
      scale 0.35
    }
    finish { Base phong 0.4 phong_size 40 }
  }
  translate <2.4, 0.7, 1.3>
}
