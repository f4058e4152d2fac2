// Hand-written POV-Ray 3.7 twin of blob-component-transforms.xml (written from POV-Ray's
// documentation, not exported). Each <component> is a blob sphere or cylinder component
// with its own transform written as POV-Ray's: scale, rotate and translate in the same
// order, a shear as POV-Ray's matrix (whose 12 numbers are the columns of Lucent's rows:
// Lucent's y += 0.6 x is matrix <1, 0.6, 0, 0, 1, 0, 0, 0, 1, 0, -0.3, 0>). Lucent's
// material (k_a, k_d, specular k_s with shininess s) is pigment k_d, ambient k_a / k_d,
// diffuse 1, specular k_s with roughness 1/s; the right vector is negated to keep Lucent's
// right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 2.6, 7>
  right -x*4/3
  up y
  angle 45
  look_at <0, 1.1, 0>
}
light_source { <-4, 7, 6> color rgb 1 }
light_source { <5, 4, 4> color rgb 0.35 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end
#declare Gold = Surface(<0.8, 0.55, 0.15>, <0.1, 0.07, 0.02>, 0.7, 60)
#declare Red = Surface(<0.85, 0.2, 0.15>, <0.1, 0.03, 0.03>, 0.7, 60)

plane { y, 0 texture { pigment { rgb 0.6 } finish { ambient 0.1 / 0.6 diffuse 1 specular 0 } } }

// An ellipsoid body on a flattened base, two sheared capsule arms.
blob {
  threshold 0.5
  sphere { 0, 1, strength 1 scale <0.8, 1.5, 0.8> translate <0, 1.4, 0> }
  sphere { 0, 1, strength 1 scale <1.4, 0.45, 1.4> translate <0, 0.35, 0> }
  cylinder { <0.5, 1.5, 0>, <1.3, 1.5, 0>, 0.35, strength 1.2
             matrix <1, 0.6, 0, 0, 1, 0, 0, 0, 1, 0, -0.3, 0> }
  cylinder { <-0.5, 1.5, 0>, <-1.3, 1.5, 0>, 0.35, strength 1.2
             matrix <1, -0.6, 0, 0, 1, 0, 0, 0, 1, 0, -0.3, 0> }
  texture { Red }
  translate <-1.3, 0, 0>
}

// A turned disc on a squashed post, a negative ellipsoid carving a groove.
blob {
  threshold 0.5
  sphere { 0, 1, strength 1.2 scale <1.3, 0.3, 0.7> rotate z*20 rotate y*40 translate <0, 1.6, 0> }
  cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.5, strength 1.5 scale <1, 1, 0.5> rotate x*-15 }
  sphere { <0, 1.2, 0.3>, 0.5, strength -1.5 scale <2.5, 0.6, 1> }
  texture { Gold }
  translate <1.4, 0, 0.3>
}
