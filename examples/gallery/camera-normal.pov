// Hand-written POV-Ray 3.7 twin of camera-normal.xml (written from POV-Ray's
// documentation, not exported). Lucent's pinhole camera with fov 50 on a 4:3 image is
// POV-Ray's perspective camera with right -x*4/3 (negative: our right-handed world,
// unchanged coordinates), up y and angle 50; its normal is the camera's normal block, and
// the ripples' three sources are global_settings' number_of_waves.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039
  number_of_waves 3 }

// Lucent's k_d, k_a, k_s, n_s: pigment k_d, ambient k_a / k_d (POV-Ray scales ambient by the
// pigment), diffuse 1, Blinn specular k_s with roughness 1 / n_s.
#macro Plastic(Kd, Ka, Ks, Ns)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end
#declare Red = Plastic(<0.85, 0.15, 0.1>, <0.1, 0.02, 0.02>, 0.5, 60)
#declare Green = Plastic(<0.15, 0.7, 0.25>, <0.02, 0.08, 0.03>, 0.5, 60)
#declare Stone = Plastic(<0.8, 0.78, 0.72>, 0.1, 0.2, 30)

background { rgb <0.35, 0.5, 0.75> }
camera {
  perspective
  location <0, 2.2, 6>
  right -x * 4 / 3
  up y
  angle 50
  look_at <0, 0.4, 0>
  normal { ripples 0.05 frequency 5 scale 0.6 }
}
light_source { <4, 7, 5> color rgb <1, 0.95, 0.9> }
light_source { <-6, 4, 2> color rgb <0.35, 0.4, 0.5> }

// The checker colour T multiplies k_d and, ambient being one number, k_a too.
plane { y, -0.5
  texture {
    pigment { checker rgb <0.85, 0.82, 0.75>, rgb <0.25, 0.24, 0.28> }
    finish { ambient 0.12 diffuse 0.9 specular 0 phong 0 reflection 0 }
  }
}
sphere { <-1.3, 0.2, 0.3>, 0.7 texture { Red } }
sphere { <0.9, 0.1, -1.0>, 0.6 texture { Green } }
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> texture { Stone } rotate y * 30 translate <1.6, 0, 1.2> }
