// Hand-written POV-Ray 3.7 twin of pattern-pigment-pattern.xml (written from POV-Ray 3.7's
// documentation, not exported). Each Lucent <pattern type="pigment-pattern"> is
// pigment_pattern { PIGMENT } with its <pigment>'s texture as the PIGMENT, the pattern's
// transform after it; the <normal> is the normal pattern with its depth. A material with a
// pattern has diffuse 1 and its single-number ambient multiplies the pattern's colour;
// without a pattern Lucent's ambient is a colour of its own, so here it is divided by the
// pigment.
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

// Left: a checker's two grey levels, times 1.5, through a colour map, bent by the
// slope of a turbulent granite's grey.
box {
  <-3.6, 0.2, -0.1>, <-0.1, 3.8, 0>
  texture {
    pigment {
      pigment_pattern {
        checker rgb <1, 0.5, 0>, rgb <0, 0.2, 1>
        scale 0.6
        translate <0, 0, 0.3>   // the face z = 0 inside a cube, not on a cube's wall
      }
      frequency 1.5
      color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.8, 0.3, 0.2>] [1 rgb <1, 0.95, 0.6>] }
    }
    normal {
      pigment_pattern { granite color_map { [0 rgb 0] [1 rgb 1] } scale 1.5 }
      0.4
      turbulence 0.3
    }
    finish { ambient 0.2 diffuse 1 specular 0 phong 0.4 phong_size 40 }
  }
}

// Right: a turned gradient's grey as the value of a pigment map.
box {
  <0.1, 0.2, -0.1>, <3.6, 3.8, 0>
  texture {
    pigment {
      pigment_pattern {
        gradient x triangle_wave
        color_map { [0 rgb <1, 0, 0>] [1 rgb <0.2, 0.9, 0.4>] }
        scale 1.2
      }
      pigment_map {
        [0.3 checker rgb <0.9, 0.9, 0.8>, rgb <0.2, 0.3, 0.5> scale 0.3 translate <0, 0, 0.15>]
        [0.6 rgb <0.7, 0.2, 0.1>]
      }
      rotate <0, 0, 30>
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
