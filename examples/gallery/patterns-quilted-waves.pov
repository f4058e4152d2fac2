// Hand-written POV-Ray 3.7 twin of patterns-quilted-waves.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern> is the pigment pattern of that name
// with its modifiers, the pattern's transform inside the pigment; quilted's default
// frequency is 0 in both. A material with a pattern has diffuse 1 and its single-number
// ambient multiplies the pattern's colour; without a pattern Lucent's ambient is a colour
// of its own, so here it is divided by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.1, 0.1, 0.15> }
camera {
  perspective
  location <0, 2, 8.2>
  right -x * 320 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 50
  look_at <0, 2, 0>
}
light_source { <-3, 6, 8> color rgb 1 }
light_source { <4, 4, 6> color rgb 0.3 }

#declare Panel = finish { ambient 0.2 diffuse 1 specular 0 phong 0 }

// Bottom left: quilted cushions, coloured and bent by quilted's own normal.
box {
  <-3.6, 0.2, -0.1>, <-0.1, 1.9, 0>
  texture {
    pigment {
      quilted control0 0.2 control1 0.9
      color_map { [0 rgb <0.9, 0.85, 0.7>] [0.3 rgb <0.7, 0.2, 0.2>] [0.6 rgb <0.2, 0.1, 0.3>] }
      scale 0.4
    }
    normal { quilted 0.6 control0 0.5 control1 0.9 scale 0.4 }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.5 phong_size 40 }
  }
}

// Bottom right: dents as a pigment (the noise cubed).
box {
  <0.1, 0.2, -0.1>, <3.6, 1.9, 0>
  texture {
    pigment {
      dents
      color_map { [0 rgb <0.1, 0.2, 0.4>] [0.2 rgb <0.4, 0.7, 0.9>] [0.6 rgb 1] }
      scale 0.3
    }
    finish { Panel }
  }
}

// Top left: ripples, three times over, shifted by a phase of 0.2.
box {
  <-3.6, 2.1, -0.1>, <-0.1, 3.8, 0>
  texture {
    pigment {
      ripples frequency 3 phase 0.2
      color_map { [0 rgb <0.05, 0.2, 0.3>] [1 rgb <0.6, 0.9, 1>] }
      scale 0.8
      translate <-1.8, 3, 0>
    }
    finish { Panel }
  }
}

// Top right: waves through a sine wave.
box {
  <0.1, 2.1, -0.1>, <3.6, 3.8, 0>
  texture {
    pigment {
      waves frequency 2 sine_wave
      color_map { [0 rgb <0.3, 0.15, 0>] [1 rgb <1, 0.8, 0.3>] }
      scale 0.7
      translate <1.8, 3, 0>
    }
    finish { Panel }
  }
}

plane {
  y, 0
  texture {
    pigment { rgb <0.5, 0.5, 0.55> }
    finish { ambient rgb <0.1 / 0.5, 0.1 / 0.5, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}
