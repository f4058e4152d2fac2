// Hand-written POV-Ray 3.7 twin of pigment-function.xml (written from POV-Ray's
// documentation, not exported). The coordinates are Lucent's, seen through a mirrored
// camera (right -x); a Lucent pattern is evaluated at the object's own point, which for
// these shapes is the point written here. Each <pigment-function> is a declared
// function { pigment { } }, called with the member its component names.
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

#declare C = function { pigment { checker rgb <1, 1, 0> rgb <0, 0, 1> rotate 45*y } }
#declare Wood = pigment {
  wood turbulence 0.1
  color_map { [0 rgb <0.9, 0.7, 0.4>] [1 rgb <0.35, 0.15, 0.05>] }
  scale 0.2 rotate 70*x rotate 20*y
}
#declare W = function { pigment { Wood } }
#declare L = function { pigment { leopard color_map { [0 rgb 0] [1 rgb 1] } scale 0.15 } }

plane { y, 0
  texture {
    pigment {
      function { 0.2 + 0.6 * C(x, y, z).blue }
      color_map { [0 rgb <0.9, 0.9, 0.85>] [1 rgb <0.25, 0.3, 0.35>] }
    }
    finish { ambient 0.15 diffuse 0.9 }
  }
}
sphere { <-1.2, 1, 0.4>, 1
  texture {
    pigment {
      function { pow(W(x, y, z).red, 2) + 0.25 * W(x, y, z).green }
      color_map { [0 rgb <0.3, 0.12, 0.04>] [1 rgb <1, 0.8, 0.5>] }
    }
    finish { ambient 0.1 diffuse 1 phong 0.5 }
  }
}
isosurface {
  function { sqrt(x*x + y*y + z*z) - 0.7 - 0.2 * L(x, y, z).gray }
  contained_by { sphere { 0, 1 } }
  max_gradient 6
  all_intersections
  // Lucent's ambient 0.1 is not scaled by the colour; POV-Ray's is.
  texture { pigment { rgb <0.4, 0.75, 0.45> } finish { ambient rgb 0.1 / <0.4, 0.75, 0.45> diffuse 1 } }
  translate <1.3, 0.95, 0>
}
