// Hand-written POV-Ray 3.7 twin of transforms.xml (written from POV-Ray's documentation,
// not exported). A node's transform applies before its parent's in Lucent, as an object's
// own transform applies before that of the union holding it in POV-Ray; rotate y*a is
// Lucent's rotate-y(a). Lucent's matrix rows (x' = x + 0.5 y) become POV-Ray's row-vector
// matrix, whose second row carries the 0.5.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

#macro Plastic(Kd, Ka, Ks, Ns)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end
#declare Brass = Plastic(<0.75, 0.55, 0.2>, <0.08, 0.06, 0.02>, 0.7, 60)
#declare Red = Plastic(<0.8, 0.2, 0.15>, <0.08, 0.02, 0.02>, 0.5, 40)
#declare Blue = Plastic(<0.2, 0.4, 0.8>, <0.02, 0.04, 0.08>, 0.5, 40)

background { rgb <0.55, 0.65, 0.8> }
camera {
  perspective
  location <0, 3.5, 7.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 55
  look_at <0, 1, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
// Directional light towards <0.4, -1, -0.5>: a parallel light far up the other way.
light_source { <-0.4, 1, 0.5> * 10000 color rgb 0.3 parallel point_at <0, 0, 0> }

plane { y, 0 Plastic(0.75, 0.12, 0, 1) }

#declare Arm = union {
  box { <0, 0, -0.12>, <1, 0.24, 0.12> }
  sphere { <1, 0.12, 0>, 0.2 }
}
// N levels above this one, each turned 35 degrees, shrunk by 0.85 and raised 0.3.
#macro Stack(N)
  union {
    object { Arm }
    #if (N > 0)
      object { Stack(N - 1) scale 0.85 rotate y * 35 translate <0, 0.3, 0> }
    #end
  }
#end
union {
  cylinder { <0, 0, 0>, <0, 0.3, 0>, 0.4 }
  object { Stack(5) translate <0, 0.3, 0> }
  texture { Brass }
  translate <-0.2, 0, -0.6>
}

// Shear x' = x + 0.5 y.
union {
  box { <-0.4, 0, -0.4>, <0.4, 1.2, 0.4> }
  sphere { <0, 1.6, 0>, 0.35 }
  texture { Red }
  matrix <1, 0, 0,  0.5, 1, 0,  0, 0, 1,  0, 0, 0>
  translate <-2.8, 0, 0.6>
}

#declare Ell = union {
  box { <0, 0, 0>, <0.3, 1.2, 0.3> }
  box { <0.3, 0, 0>, <0.9, 0.3, 0.3> }
  cone { <0.15, 1.2, 0.15>, 0.15, <0.7, 1.2, 0.15>, 0 }
}
object { Ell texture { Blue } rotate y * -20 translate <1.6, 0, 0.8> }
object { Ell texture { Blue } rotate y * -20 scale <-1, 1, 1> translate <1.3, 0, 0.8> }
