// Hand-written POV-Ray 3.7 twin of patterns-tiling.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type="tiling" tiling="N"> is the
// pigment `tiling N` with its colour map and the pattern's transform inside the pigment.
// A material with a pattern has diffuse 1 and its single-number ambient multiplies the
// pattern's colour; without a pattern Lucent's ambient is a colour of its own, so here it
// is divided by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.1, 0.1, 0.15> }
camera {
  perspective
  location <0, 10, -6.5>
  right -x * 320 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 50
  look_at <0, 0, 1.6>
}
light_source { <-3, 12, -6> color rgb 1 }
light_source { <5, 8, -4> color rgb 0.3 }

box {
  <-5.3, 0, -0.2>, <-1.9, 0.1, 2.8>
  texture {
    pigment {
      tiling 5
      color_map { [0 rgb <0.9, 0.85, 0.7>] [0.3 rgb <0.8, 0.75, 0.6>] [0.333 rgb <0.1, 0.1, 0.1>] [0.334 rgb <0.3, 0.45, 0.7>] [0.63 rgb <0.25, 0.4, 0.6>] [0.666 rgb <0.1, 0.1, 0.1>] [0.667 rgb <0.7, 0.3, 0.2>] [0.97 rgb <0.6, 0.25, 0.15>] [1 rgb <0.1, 0.1, 0.1>] }
      scale 0.45
      translate <-3.6, 0, 1.3>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <-1.7, 0, -0.2>, <1.7, 0.1, 2.8>
  texture {
    pigment {
      tiling 7
      color_map { [0 rgb <0.95, 0.95, 0.9>] [0.45 rgb <0.8, 0.8, 0.75>] [0.5 rgb <0.2, 0.2, 0.2>] [0.5 rgb <0.2, 0.5, 0.3>] [0.9 rgb <0.15, 0.4, 0.25>] [1 rgb <0.05, 0.1, 0.05>] }
      scale 0.5
      translate <0, 0, 1.3>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <1.9, 0, -0.2>, <5.3, 0.1, 2.8>
  texture {
    pigment {
      tiling 16
      color_map { [0 rgb <0.9, 0.8, 0.3>] [0.3 rgb <0.8, 0.7, 0.25>] [0.333 rgb <0.1, 0.1, 0.1>] [0.334 rgb <0.85, 0.85, 0.85>] [0.63 rgb <0.7, 0.7, 0.7>] [0.666 rgb <0.1, 0.1, 0.1>] [0.667 rgb <0.2, 0.3, 0.7>] [0.97 rgb <0.15, 0.25, 0.6>] [1 rgb <0.05, 0.05, 0.1>] }
      scale 0.4
      translate <3.6, 0, 1.3>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <-5.3, 0, 3.2>, <-1.9, 0.1, 6.2>
  texture {
    pigment {
      tiling 22
      color_map { [0 rgb <0.8, 0.2, 0.2>] [0.3 rgb <0.7, 0.15, 0.15>] [0.333 rgb <0.1, 0.1, 0.1>] [0.334 rgb <0.9, 0.6, 0.2>] [0.63 rgb <0.8, 0.5, 0.15>] [0.666 rgb <0.1, 0.1, 0.1>] [0.667 rgb <0.95, 0.95, 0.85>] [0.97 rgb <0.85, 0.85, 0.75>] [1 rgb <0.1, 0.1, 0.1>] }
      scale 0.35
      translate <-3.6, 0, 4.7>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <-1.7, 0, 3.2>, <1.7, 0.1, 6.2>
  texture {
    pigment {
      tiling 26
      color_map { [0 rgb <0.9, 0.7, 0.3>] [0.45 rgb <0.8, 0.6, 0.25>] [0.5 rgb <0.1, 0.1, 0.1>] [0.5 rgb <0.3, 0.2, 0.5>] [0.9 rgb <0.4, 0.3, 0.6>] [1 rgb <0.1, 0.1, 0.1>] }
      scale 0.6
      translate <0, 0, 4.7>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <1.9, 0, 3.2>, <5.3, 0.1, 6.2>
  texture {
    pigment {
      tiling 27
      color_map { [0 rgb <0.3, 0.6, 0.8>] [0.45 rgb <0.4, 0.7, 0.9>] [0.5 rgb <0.1, 0.1, 0.1>] [0.5 rgb <0.9, 0.9, 0.8>] [0.9 rgb <0.8, 0.8, 0.7>] [1 rgb <0.1, 0.1, 0.1>] }
      scale 0.5
      translate <3.6, 0, 4.7>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

plane {
  y, 0
  texture {
    pigment { rgb <0.5, 0.5, 0.55> }
    finish { ambient rgb <0.1 / 0.5, 0.1 / 0.5, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}
