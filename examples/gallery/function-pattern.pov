// Hand-written POV-Ray 3.7 twin of function-pattern.xml (written from POV-Ray's
// documentation, not exported). The coordinates are Lucent's, seen through a mirrored
// camera (right -x); a Lucent pattern is evaluated at the object's own point, which for
// these shapes is the point written here.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 2.4, 6.5>
  right -x * 240 / 180
  up y
  angle 50
  look_at <0, 0.9, 0>
}
light_source { <-3, 6, 5> color rgb 1 }

plane { y, 0
  texture {
    pigment {
      function { sin(2 * x) - 0.3 * cos(3 * z) }
      color_map { [0 rgb <0.9, 0.9, 0.85>] [1 rgb <0.25, 0.3, 0.35>] }
    }
    finish { ambient 0.15 diffuse 0.9 }
  }
}
sphere { <-1.2, 1, 0.4>, 1
  texture {
    pigment {
      function { 0.5 + 0.5 * sin(6 * x) * cos(6 * y) }
      color_map { [0 rgb <1, 0.45, 0.1>] [0.5 rgb <1, 0.9, 0.6>] [1 rgb <0.2, 0.3, 0.9>] }
    }
    finish { ambient 0.1 diffuse 1 phong 0.5 }
  }
}
box { <0.3, 0, -1>, <2.3, 1.6, 0.6>
  texture {
    pigment {
      function { x * x + z * z }
      color_map { [0 rgb <0.1, 0.6, 0.3>] [0.5 rgb <0.95, 0.95, 0.8>] [1 rgb <0.1, 0.6, 0.3>] }
      scale 0.6
    }
    finish { ambient 0.1 diffuse 1 }
  }
}
