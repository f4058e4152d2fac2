// Hand-written POV-Ray 3.7 twin of checker.xml (written from POV-Ray's documentation, not
// exported). Lucent's <checker scale="s"> is POV-Ray's `checker` pigment scaled by s, the
// cube [0, s)^3 in color1. Lucent evaluates it in the shape's object space: in POV-Ray the
// texture is written before the object's transforms, so it turns and shrinks with them.
// With a texture Lucent's diffuse defaults to 1, and a one-number ambient is scaled by the
// texture colour, as POV-Ray scales ambient by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

#macro Checker(C1, C2, S, Ka, Kd, Ks, Ns)
  texture {
    pigment { checker rgb C1, rgb C2 scale S }
    finish { ambient Ka diffuse Kd specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end

background { rgb <0.45, 0.55, 0.7> }
camera {
  perspective
  location <0, 3.2, 6.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.7, 0>
}
light_source { <-3, 6, 5> color rgb 1 }
// Directional light towards <0.5, -1, -0.3>: a parallel light far up the other way.
light_source { <-0.5, 1, 0.3> * 10000 color rgb 0.3 parallel point_at <0, 0, 0> }

plane { y, 0 Checker(<0.9, 0.9, 0.85>, <0.25, 0.3, 0.35>, 1, 0.15, 0.9, 0, 1) }
box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6>
  Checker(<0.95, 0.8, 0.2>, <0.7, 0.15, 0.1>, 0.3, 0.15, 1, 0.3, 30)
  rotate y * 30
  rotate x * 15
  translate <-1.6, 0.8, 0>
}
sphere { <0, 0, 0>, 1
  Checker(0.95, <0.1, 0.3, 0.8>, 0.4, 0.15, 1, 0.5, 60)
  scale 0.8
  rotate z * 20
  translate <0.4, 0.8, 0>
}
// No specular in Lucent's material: specular 0 (the roughness is then irrelevant).
cylinder { <2, 0, -0.5>, <2, 1.5, -0.5>, 0.45
  Checker(<0.3, 0.8, 0.3>, <0.1, 0.2, 0.1>, 0.25, 0.15, 1, 0, 64)
}
