// Hand-written POV-Ray 3.7 twin of patterns-blocks.xml (written from POV-Ray 3.7's
// documentation, not exported). Lucent's <brick color1 color2 mortar size> is POV-Ray's brick
// (the first colour is the mortar's) with brick_size and mortar; <hexagon> is hexagon with
// its three colours (Lucent's defaults: blue, green, red); a <pattern> without a colour map
// is the grey map from black to white. The spheres use center="...", so their patterns sit
// in world space: here the pigments are not moved with the spheres. A material with a
// texture has diffuse 1, and its single-number ambient multiplies the texture's colour, as
// POV-Ray's ambient multiplies the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 2.5, 8>
  right -x * 320 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-5, 8, 7> color rgb 1 }

#declare Plain = finish { ambient 0.1 diffuse 1 brilliance 1 specular 0 phong 0 reflection 0 }

plane {
  y, 0
  texture {
    pigment { brick rgb <0.8, 0.8, 0.75>, rgb <0.55, 0.2, 0.1> brick_size <1, 0.5, 0.5> mortar 0.1 }
    finish { Plain }
  }
}
sphere {
  <-2.4, 1, 0>, 1
  texture {
    pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 0.5 }
    finish { Plain }
  }
}
sphere {
  <0, 1, 0>, 1
  texture {
    pigment { onion color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 }
    finish { Plain }
  }
}
sphere {
  <2.4, 1, 0>, 1
  texture {
    pigment { hexagon rgb <0, 0, 1>, rgb <0, 1, 0>, rgb <1, 0, 0> scale 0.25 }
    finish { Plain }
  }
}
