// Hand-written POV-Ray 3.7 twin of reflection-angle.xml (written from POV-Ray's
// documentation, not exported): reflection { MIN, MAX falloff }, reflection { MIN, MAX
// fresnel } on an opaque sphere with an interior, a glass with a fresnel reflection over a
// floor and conserve_energy, and reflection { exponent }.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.25, 0.3, 0.4> }
camera {
  perspective
  location <0, 2.4, 8>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <6, 5, 8> color rgb 0.4 }

plane { y, 0
  texture {
    pigment { checker rgb <0.9, 0.85, 0.75>, rgb <0.2, 0.3, 0.5> scale 0.5 }
    finish { ambient 0.1 diffuse 0.8 specular 0 phong 0 reflection 0 }
  }
}
// Grows from 0.05 facing the viewer to 0.9 at the rim, by (1 - cos)^2.
sphere { <-3, 0.8, 0>, 0.8
  texture {
    pigment { rgb <0.8, 0.2, 0.15> }
    finish { ambient 0.05 diffuse 0.6 specular 0 phong 0 reflection { 0.05, 0.9 falloff 2 } }
  }
}
// Fresnel reflection over a floor of 0.15: the interior's index decides F.
sphere { <-1, 0.8, 0>, 0.8
  texture {
    pigment { rgb <0.15, 0.3, 0.7> }
    finish { ambient 0.05 diffuse 0.6 specular 0 phong 0 reflection { 0.15, 1 fresnel } }
  }
  interior { ior 1.8 }
}
// Glass: fresnel reflection from 0.05 to 0.8, and conserve_energy takes it from the light
// let through.
sphere { <1, 0.8, 0>, 0.8
  texture {
    pigment { rgbf <1, 1, 1, 0.9> }
    finish { ambient 0 diffuse 0.5 specular 0.6 roughness 0.005 phong 0
             reflection { 0.05, 0.8 fresnel } conserve_energy }
  }
  interior { ior 1.5 }
}
// The reflected light raised to 1/2.5: dim reflections come up.
sphere { <3, 0.8, 0>, 0.8
  texture {
    pigment { rgb <0.7, 0.6, 0.2> }
    finish { ambient 0.05 diffuse 0.4 specular 0 phong 0 reflection { 0.5 exponent 2.5 } }
  }
}
