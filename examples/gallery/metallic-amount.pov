// Hand-written POV-Ray 3.7 twin of metallic-amount.xml (written from POV-Ray's
// documentation, not exported). Each sphere's pigment is Lucent's metallic-color and its
// diffuse the factor that makes pigment × diffuse Lucent's diffuse colour; POV-Ray's
// metallic amount is metallic-amount, its reflection { metallic } reflect-metallic.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.25, 0.3, 0.4> }
camera {
  perspective
  location <0, 2.2, 7>
  right -x * 240 / 180   // negative: our right-handed world, unchanged coordinates
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
sphere { <-2, 0.8, 0>, 0.8
  texture {
    pigment { rgb <0.9, 0.6, 0.2> }
    finish { ambient 0 diffuse 0.5 specular 0 phong 0.9 phong_size 30 metallic 0.5 reflection 0 }
  }
}
sphere { <0, 0.8, 0>, 0.8
  texture {
    pigment { rgb <0.3, 0.5, 0.9> }
    finish { ambient 0 diffuse 0.4 specular 0 phong 0.8 phong_size 12 metallic reflection 0 }
  }
}
sphere { <2, 0.8, 0>, 0.8
  texture {
    pigment { rgb <0.9, 0.7, 0.3> }
    finish { ambient 0 diffuse 0.3 specular 0 phong 0 reflection { 0.7 metallic 1 } }
  }
}
