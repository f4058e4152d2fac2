// Hand-written POV-Ray 3.7 twin of patterns-shapes.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern> is the pigment pattern of that name
// with its modifiers, the pattern's transform inside the pigment, and each <normal> the
// normal pattern with its depth. A material with a pattern has diffuse 1 and its
// single-number ambient multiplies the pattern's colour; without a pattern Lucent's ambient
// is a colour of its own, so here it is divided by the pigment.
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

// Bottom left: spherical, a glow about the panel's centre, bent by a spherical normal.
box {
  <-3.6, 0.2, -0.1>, <-0.1, 1.9, 0>
  texture {
    pigment {
      spherical
      color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.8, 0.3, 0.2>] [1 rgb <1, 0.95, 0.6>] }
      scale 1.5
      translate <-1.85, 1.05, 0>
    }
    normal { spherical 0.8 scale 0.8 translate <-1.85, 1.05, 0> }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.4 phong_size 40 }
  }
}

// Bottom right: cylindrical about a tilted axis, three sine waves across its band.
box {
  <0.1, 0.2, -0.1>, <3.6, 1.9, 0>
  texture {
    pigment {
      cylindrical frequency 3 sine_wave
      color_map { [0 rgb <0.05, 0.25, 0.2>] [1 rgb <0.7, 1, 0.8>] }
      scale 1.4
      rotate <0, 0, 30>
      translate <1.85, 1.05, 0>
    }
    finish { Panel }
  }
}

// Top left: boxed turned into a diamond, with a boxed normal (a pyramid).
box {
  <-3.6, 2.1, -0.1>, <-0.1, 3.8, 0>
  texture {
    pigment {
      boxed
      color_map { [0 rgb <0.3, 0.15, 0>] [0.4 rgb <0.9, 0.6, 0.2>] [1 rgb <1, 1, 0.9>] }
      scale 0.8
      rotate <0, 0, 45>
      translate <-1.85, 2.95, 0>
    }
    normal { boxed 0.6 scale 0.7 rotate <0, 0, 45> translate <-1.85, 2.95, 0> }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.4 phong_size 40 }
  }
}

// Top right: cells, one colour for each cube of side 0.35.
box {
  <0.1, 2.1, -0.1>, <3.6, 3.8, 0>
  texture {
    pigment {
      cells
      color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 0.9>] [1 rgb <0.8, 0.1, 0.1>] }
      scale 0.35
      translate <0, 0, 0.17>   // the face z = 0 inside a cube, not on a cube's wall
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
