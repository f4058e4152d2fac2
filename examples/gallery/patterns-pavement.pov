// Hand-written POV-Ray 3.7 twin of patterns-pavement.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type="pavement"> is the pigment
// `pavement` with number_of_sides, number_of_tiles, pattern, exterior, interior and form,
// its colour map and the pattern's transform inside the pigment. A material with a pattern
// has diffuse 1 and its single-number ambient multiplies the pattern's colour; without a
// pattern Lucent's ambient is a colour of its own, so here it is divided by the pigment.
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
      pavement
      number_of_sides 3 number_of_tiles 6 pattern 7
      exterior 1 interior 2 form 0
      color_map { [0 rgb <0.9, 0.85, 0.7>] [0.45 rgb <0.765, 0.722, 0.595>] [0.55 rgb <0.7, 0.3, 0.2>] [1 rgb <0.7, 0.3, 0.2>] }
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
      pavement
      number_of_sides 4 number_of_tiles 5 pattern 8
      exterior 0 interior 2 form 0
      color_map { [0 rgb <0.95, 0.95, 0.9>] [0.45 rgb <0.807, 0.807, 0.765>] [0.55 rgb <0.2, 0.5, 0.3>] [1 rgb <0.2, 0.5, 0.3>] }
      scale 0.4
      translate <0, 0, 1.3>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <1.9, 0, -0.2>, <5.3, 0.1, 2.8>
  texture {
    pigment {
      pavement
      number_of_sides 4 number_of_tiles 6 pattern 30
      exterior 2 interior 1 form 2
      color_map { [0 rgb <0.9, 0.8, 0.3>] [0.45 rgb <0.765, 0.68, 0.255>] [0.55 rgb <0.2, 0.3, 0.7>] [1 rgb <0.2, 0.3, 0.7>] }
      scale 0.35
      translate <3.6, 0, 1.3>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <-5.3, 0, 3.2>, <-1.9, 0.1, 6.2>
  texture {
    pigment {
      pavement
      number_of_sides 6 number_of_tiles 4 pattern 5
      exterior 0 interior 0 form 0
      color_map { [0 rgb <0.8, 0.2, 0.2>] [0.45 rgb <0.68, 0.17, 0.17>] [0.55 rgb <0.95, 0.95, 0.85>] [1 rgb <0.95, 0.95, 0.85>] }
      scale 0.3
      translate <-3.6, 0, 4.7>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <-1.7, 0, 3.2>, <1.7, 0.1, 6.2>
  texture {
    pigment {
      pavement
      number_of_sides 6 number_of_tiles 5 pattern 16
      exterior 0 interior 2 form 1
      color_map { [0 rgb <0.3, 0.2, 0.5>] [0.45 rgb <0.255, 0.17, 0.425>] [0.55 rgb <0.9, 0.7, 0.3>] [1 rgb <0.9, 0.7, 0.3>] }
      scale 0.25
      translate <0, 0, 4.7>
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
  }
}

box {
  <1.9, 0, 3.2>, <5.3, 0.1, 6.2>
  texture {
    pigment {
      pavement
      number_of_sides 3 number_of_tiles 5 pattern 4
      exterior 2 interior 1 form 2
      color_map { [0 rgb <0.3, 0.6, 0.8>] [0.45 rgb <0.255, 0.51, 0.68>] [0.55 rgb <0.1, 0.1, 0.1>] [1 rgb <0.1, 0.1, 0.1>] }
      scale 0.4
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
