// Hand-written POV-Ray 3.7 twin of blob.xml (written from POV-Ray's documentation, not
// exported). Each <component> is a blob sphere or cylinder component with its strength;
// threshold as in the scene. Lucent's material (k_a, k_d, specular k_s with shininess s) is
// pigment k_d, ambient k_a / k_d, diffuse 1, specular k_s with roughness 1/s; the right
// vector is negated to keep Lucent's right-handed axes.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.4, 7.2>
  right -x*4/3
  up y
  angle 48
  look_at <0, 0.7, 0>
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
#declare Blue = Surface(<0.2, 0.45, 0.85>, <0.03, 0.06, 0.1>, 0.7, 60)
#declare Red = Surface(<0.85, 0.2, 0.15>, <0.1, 0.03, 0.03>, 0.7, 60)
#declare Green = Surface(<0.2, 0.7, 0.3>, <0.03, 0.1, 0.04>, 0.7, 60)

plane { y, 0 texture { pigment { rgb 0.6 } finish { ambient 0.1 / 0.6 diffuse 1 specular 0 } } }

// Three merging spheres bitten by a negative one.
blob {
  threshold 0.5
  sphere { <-0.4, 0.7, 0>, 1, strength 1 }
  sphere { <0.4, 0.7, 0>, 1, strength 1 }
  sphere { <0, 1.4, 0>, 0.9, strength 1 }
  sphere { <0.3, 1.1, 0.6>, 0.6, strength -2 }
  texture { Red }
  translate <-2, 0, -1>
}

// A cross of two cylinders with round ends and two spheres.
blob {
  threshold 0.6
  cylinder { <-0.9, 0.5, 0>, <0.9, 0.5, 0>, 0.45, strength 1.2 }
  cylinder { <0, 0.2, 0>, <0, 1.6, 0>, 0.4, strength 1.2 }
  sphere { <-0.9, 0.5, 0>, 0.7, strength 1.5 }
  sphere { <0.9, 0.5, 0>, 0.7, strength 1.5 }
  texture { Green }
  rotate y*30
  translate <0.6, 0, -1.6>
}

// A ring of six spheres.
blob {
  threshold 0.4
  sphere { <0.6, 0, 0>, 0.55, strength 1 }
  sphere { <0.3, 0, 0.52>, 0.55, strength 1 }
  sphere { <-0.3, 0, 0.52>, 0.55, strength 1 }
  sphere { <-0.6, 0, 0>, 0.55, strength 1 }
  sphere { <-0.3, 0, -0.52>, 0.55, strength 1 }
  sphere { <0.3, 0, -0.52>, 0.55, strength 1 }
  texture { Gold }
  translate <2.2, 0.45, -0.6>
}

// A box hollowed by a blob; the cut faces keep the blob's colour.
difference {
  box { <-0.9, 0, -0.5>, <0.9, 0.9, 0.5> texture { Blue } }
  blob {
    threshold 0.5
    sphere { <-0.35, 0.9, 0>, 0.8, strength 1 }
    sphere { <0.35, 0.9, 0>, 0.8, strength 1 }
    cylinder { <-0.6, 0.9, 0.3>, <0.6, 0.9, 0.3>, 0.3, strength 1 }
    texture { Gold }
  }
  rotate y*-25
  translate <-0.4, 0, 1.2>
}
