// Hand-written POV-Ray 3.7 twin of pattern-planar.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type="planar"> is the pigment pattern
// planar with its modifiers, the pattern's transform inside the pigment (first operation
// first) and the sphere's after the texture, so that the pattern moves with the sphere. A
// material with a pattern has diffuse 1 and its single-number ambient multiplies the
// pattern's colour, as POV-Ray's ambient does; without a pattern Lucent's ambient is a colour
// of its own, so here it is divided by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.2, 0.25, 0.35> }
camera {
  perspective
  location <0, 1.6, 8>
  right -x * 320 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 50
  look_at <0, 1.1, 0>
}
light_source { <-4, 7, 8> color rgb 1 }
light_source { <5, 3, 6> color rgb 0.3 }

// The wall: planar three times over, tilted by 25 degrees and centred at y = 2.5.
box {
  <-6, 0, -3>, <6, 5, -2.5>
  texture {
    pigment {
      planar
      frequency 3
      color_map { [0 rgb <0.25, 0.3, 0.45>] [0.6 rgb <0.5, 0.55, 0.7>] [1 rgb <0.95, 0.9, 0.6>] }
      rotate 25 * z
      scale 1.5
      translate 2.5 * y
    }
    finish { ambient 0.15 diffuse 1 specular 0 phong 0 }
  }
}

plane {
  y, 0
  texture {
    pigment { rgb <0.6, 0.58, 0.55> }
    finish { ambient rgb <0.1 / 0.6, 0.1 / 0.58, 0.1 / 0.55> diffuse 1 specular 0 phong 0 }
  }
}

// Left: a golden band round the equator, half a unit either side of it.
sphere {
  0, 1
  texture {
    pigment { planar color_map { [0 rgb <0.15, 0.2, 0.6>] [1 rgb <1, 0.8, 0.2>] } scale 0.5 }
    finish { ambient 0.1 diffuse 1 specular 0 phong 0 }
  }
  translate <-2.3, 1, 0>
}

// Middle: planar through a sine wave, twice over, tilted about x (grey levels, no map).
sphere {
  0, 1
  texture {
    pigment { planar sine_wave frequency 2 rotate 60 * x scale 0.7 }
    finish { ambient 0.1 diffuse 1 specular 0 phong 0 }
  }
  translate <0, 1, 0>
}

// Right: a plain red sphere whose normal carries planar's ridge, slightly tilted.
sphere {
  0, 1
  texture {
    pigment { rgb <0.8, 0.3, 0.25> }
    normal { planar 3 scale 0.35 rotate -20 * z }
    finish { ambient rgb <0.1 / 0.8, 0.1 / 0.3, 0.1 / 0.25> diffuse 1 specular 0 phong 0.6 phong_size 40 }
  }
  translate <2.3, 1, 0>
}
