// Hand-written POV-Ray 3.7 twin of patterns-fractals.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern> is the pigment pattern of that name
// with its modifiers: iterations after the keyword, power as exponent, c as julia's
// constant, exterior and interior as written; the pattern's transform inside the pigment.
// A material with a pattern has diffuse 1 and its single-number ambient multiplies the
// pattern's colour; without a pattern Lucent's ambient is a colour of its own, so here it
// is divided by the pigment.
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

// Bottom left: the Mandelbrot set, its escape count through the map, and its slope as the
// normal.
box {
  <-3.6, 0.2, -0.1>, <-0.1, 1.9, 0>
  texture {
    pigment {
      mandel 40
      color_map { [0 rgb <0.05, 0.05, 0.3>] [0.3 rgb <0.2, 0.6, 1>] [0.6 rgb <1, 0.9, 0.4>] [1 rgb <0.6, 0.1, 0.1>] }
      scale 0.8
      translate <-1.5, 1.05, 0>
    }
    normal { mandel 40 0.15 scale 0.8 translate <-1.5, 1.05, 0> }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.6 phong_size 40 }
  }
}

// Bottom right: a cubic Julia set; inside, the orbit's closest approach to 0.
box {
  <0.1, 0.2, -0.1>, <3.6, 1.9, 0>
  texture {
    pigment {
      julia <-0.5, 0.5>, 25
      exponent 3
      interior 1, 1
      color_map { [0 rgb <1, 1, 0.8>] [0.5 rgb <0.9, 0.3, 0.1>] [1 rgb <0.1, 0, 0.2>] }
      scale 0.8
      translate <1.85, 1.05, 0>
    }
    finish { Panel }
  }
}

// Top left: magnet type 1, Mandelbrot form.
box {
  <-3.6, 2.1, -0.1>, <-0.1, 3.8, 0>
  texture {
    pigment {
      magnet 1 mandel 30
      interior 1, 0.5
      color_map { [0 rgb <0.1, 0.3, 0.1>] [0.5 rgb <0.5, 0.9, 0.3>] [1 rgb 1] }
      scale 0.5
      translate <-2.4, 2.95, 0>
    }
    finish { Panel }
  }
}

// Top right: magnet type 2, Julia form; outside, |z| when it escapes over 100.
box {
  <0.1, 2.1, -0.1>, <3.6, 3.8, 0>
  texture {
    pigment {
      magnet 2 julia <1.5, 0.2>, 25
      exterior 6, 0.01
      color_map { [0 rgb <0.3, 0.1, 0.4>] [1 rgb <1, 0.7, 0.9>] }
      scale 0.35
      translate <1.85, 2.95, 0>
    }
    finish { Panel }
  }
}

// The floor.
plane {
  y, 0
  texture {
    pigment { rgb <0.5, 0.5, 0.55> }
    finish { ambient rgb <0.1 / 0.5, 0.1 / 0.5, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}
