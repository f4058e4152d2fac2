// Hand-written POV-Ray 3.7 twin of pattern-slope.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent slope is POV-Ray's slope pattern: direction is
// the slope vector, slope-range its low and high slope, altitude and altitude-range its
// altitude vector and range, point-at its point_at. A material with a pattern has diffuse 1
// and its single-number ambient multiplies the pattern's colour; the floor's ambient is a
// colour of its own, so here it is divided by the pigment.
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

#declare Panel = finish { ambient 0.2 diffuse 1 specular 0 phong 0 }

// Left: the angle to straight up.
sphere {
  <-2.6, 1.2, 0>, 1.1
  texture {
    pigment {
      slope y
      color_map { [0 rgb <0.1, 0.05, 0.02>] [0.5 rgb <0.5, 0.4, 0.3>] [0.8 rgb 0.6] [0.85 rgb 1] }
    }
    finish { Panel }
  }
}

// Middle: a steep downward direction weighed 3 to 1 against the height along y.
sphere {
  <0, 1.2, 0>, 1.1
  texture {
    pigment {
      slope { -y * 3, 0, 0.5 altitude y, 0.1, 2.3 }
      color_map {
        [0 rgb <0.1, 0.5, 0.1>] [0.45 rgb <0.2, 0.6, 0.1>] [0.55 rgb <0.6, 0.5, 0.35>]
        [0.7 rgb 0.5] [1 rgb <0.9, 0.9, 1>]
      }
    }
    finish { Panel }
  }
}

// Right: the angle to the way towards a point, twice over through a sine wave.
sphere {
  <2.6, 1.2, 0>, 1.1
  texture {
    pigment {
      slope { point_at <6, 5, 4> }
      color_map { [0 rgb <0.6, 0.1, 0.1>] [1 rgb <1, 0.85, 0.3>] }
      frequency 2
      sine_wave
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
