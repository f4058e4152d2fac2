// Hand-written POV-Ray 3.7 twin of lamps.xml (written from POV-Ray's documentation, not
// exported). The lamp is one union of a post, a no_shadow bulb and a light_source inside
// it, declared once and placed by object { Lamp transform }: POV-Ray moves the light with
// its union, as Lucent places a <light> in its <use>'s frame. The light's attenuation
// 1/(1 + 0.25 r^2) is POV-Ray's fade 2/(1 + (r/2)^2) with half the colour.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.05 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.01, 0.01, 0.03> }
camera {
  perspective
  location <0, 3.2, 7.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 55
  look_at <0, 0.8, -1>
}

#declare Lamp = union {
  cylinder {
    <0, 0, 0>, <0, 1.6, 0>, 0.05
    texture { pigment { rgb 0.2 } finish { ambient 1 diffuse 1 specular 0.6 roughness 1 / 80 phong 0 reflection 0 } }
  }
  sphere {
    <0, 1.8, 0>, 0.15
    texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 emission rgb <1, 0.85, 0.55> } }  // emission is times the pigment
    no_shadow
  }
  light_source {
    <0, 1.8, 0>
    color rgb <1, 0.85, 0.55> * 0.9 / 2
    fade_distance 2 fade_power 2
  }
}

plane {
  y, 0
  texture { pigment { rgb <0.75, 0.75, 0.8> } finish { ambient rgb 0.3 / <0.75, 0.75, 0.8> diffuse 1 specular 0 phong 0 reflection 0 } }
}

#local I = 0;
#while (I < 4)
  object { Lamp translate <-4.5 + 3 * I, 0, -2.5> }
  #local I = I + 1;
#end
// Coordinates are kept as they are (only the camera's right is mirrored), so POV-Ray's
// rotate <0, 30, 0>, which turns +x towards -z, is Lucent's rotate-y(30).
object { Lamp scale 1.4 rotate <0, 30, 0> translate <2.6, 0, 1.6> }

sphere {
  <-1.5, 0.6, -0.8>, 0.6
  texture { pigment { rgb <0.8, 0.3, 0.15> } finish { ambient rgb <0.3, 0.1, 0.05> / <0.8, 0.3, 0.15> diffuse 1 specular 0.5 roughness 1 / 60 phong 0 reflection 0 } }
}
box {
  <0.8, 0, -1.4>, <1.8, 1, -0.4>
  texture { pigment { rgb <0.2, 0.45, 0.7> } finish { ambient rgb <0.1, 0.2, 0.3> / <0.2, 0.45, 0.7> diffuse 1 specular 0.3 roughness 1 / 40 phong 0 reflection 0 } }
  rotate <0, 20, 0>
}
