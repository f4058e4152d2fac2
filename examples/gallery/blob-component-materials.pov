// Hand-written POV-Ray 3.7 twin of blob-component-materials.xml (written from POV-Ray's
// documentation, not exported). Lucent's material (k_a, k_d, specular k_s with shininess
// s) is pigment k_d, ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; a
// component's material is its texture; the right vector is negated to keep Lucent's
// right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 2.2, 9>
  right -x*4/3
  up y
  angle 45
  look_at <0, 0.1, 0>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <4, 3, 6> color rgb 0.4 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end
#declare Red = Surface(<0.85, 0.15, 0.1>, <0.09, 0.02, 0.02>, 0.5, 40)
#declare Orange = Surface(<0.9, 0.5, 0.1>, <0.09, 0.05, 0.01>, 0.5, 40)
#declare Yellow = Surface(<0.9, 0.8, 0.15>, <0.09, 0.08, 0.02>, 0.5, 40)
#declare Green = Surface(<0.2, 0.7, 0.3>, <0.02, 0.07, 0.03>, 0.5, 40)
#declare Cyan = Surface(<0.15, 0.7, 0.8>, <0.02, 0.07, 0.08>, 0.5, 40)
#declare Blue = Surface(<0.15, 0.25, 0.9>, <0.02, 0.03, 0.09>, 0.5, 40)
#declare Gold = Surface(<0.85, 0.65, 0.2>, <0.09, 0.07, 0.02>, 0.7, 60)
#declare Pale = Surface(<0.8, 0.8, 0.7>, <0.08, 0.08, 0.07>, 0.4, 40)
#declare Violet = Surface(<0.6, 0.3, 0.8>, <0.06, 0.03, 0.08>, 0.4, 40)

// A ring of six coloured spheres crossed by two cylinders; one cylinder has no texture of
// its own and shows the blob's.
blob {
  threshold 0.6
  sphere { <1.6, 0, 0>, 0.8, 1 texture { Red } }
  sphere { <0.8, 1.3856406460551018, 0>, 0.8, 1 texture { Orange } }
  sphere { <-0.8, 1.3856406460551018, 0>, 0.8, 1 texture { Yellow } }
  sphere { <-1.6, 0, 0>, 0.8, 1 texture { Green } }
  sphere { <-0.8, -1.3856406460551018, 0>, 0.8, 1 texture { Cyan } }
  sphere { <0.8, -1.3856406460551018, 0>, 0.8, 1 texture { Blue } }
  cylinder { <-2, -2, 0>, <2, 2, 0>, 0.45, 1 }
  cylinder { <-2, 2, 0>, <2, -2, 0>, 0.45, 1 texture { Blue } }
  texture { Pale }
  scale 0.75 rotate -15*y translate <-1.9, 0.7, 0>
}
// A caterpillar of gold and green spheres, dented by a negative sphere without a texture.
blob {
  threshold 0.5
  sphere { <-1.2, 0, 0>, 0.75, 1 texture { Gold } }
  sphere { <-0.6, 0, 0>, 0.75, 1 texture { Green } }
  sphere { <0, 0, 0>, 0.75, 1 texture { Gold } }
  sphere { <0.6, 0, 0>, 0.75, 1 texture { Green } }
  sphere { <1.2, 0, 0>, 0.75, 1 texture { Gold } }
  sphere { <0, 0.5, 0>, 0.5, -1 }
  texture { Violet }
  rotate 25*y translate <2.1, 0.1, 0>
}
plane {
  y, -1.4
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}
