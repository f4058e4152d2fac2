// Hand-written POV-Ray 3.7 twin of sky.xml (written from POV-Ray 3.7's documentation, not
// exported). Lucent's <sky> is POV-Ray's sky_sphere: its pattern is evaluated on the
// direction of each ray that leaves the scene, and the sky's transform is the sky_sphere's
// own (scale, then translate). Lucent's max-depth is max_trace_level; reflective k_r is
// reflection; specular k_s with shininess n_s is specular k_s with roughness 1/n_s; a
// single-number ambient of a plain colour is not multiplied by the diffuse colour in Lucent,
// so it becomes ambient k_a/k_d here, where POV-Ray multiplies ambient by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0.0039 }

background { rgb 0 }
camera {
  perspective
  location <0, 1.8, 8>
  right -x * 400 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 60
  look_at <0, 1.6, 0>
}
light_source { <-6, 9, 8> color rgb 1 }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0    rgb <0.95, 0.7, 0.45>]
      [0.08 rgb <0.9, 0.82, 0.72>]
      [0.2  rgb <0.5, 0.62, 0.9>]
      [0.35 rgb <0.2, 0.33, 0.78>]
      [1    rgb <0.05, 0.1, 0.4>]
    }
  }
  scale <1, 1.2, 1>
  translate <0, -0.05, 0>
}

// The checker multiplies both the diffuse 0.8 and the ambient 0.1, as POV-Ray's pigment does.
plane {
  y, 0
  texture {
    pigment { checker rgb <0.9, 0.9, 0.88>, rgb <0.3, 0.3, 0.32> }
    finish { ambient 0.1 diffuse 0.8 brilliance 1 specular 0 phong 0 reflection 0.1 }
  }
}

// The mirror: a dark diffuse, a sharp highlight and reflection 0.9.
sphere {
  <0, 1.2, 0>, 1.2
  texture {
    pigment { rgb 1 }
    finish { ambient 0 diffuse 0.05 brilliance 1 specular 0.8 roughness 1 / 200 phong 0 reflection 0.9 }
  }
}

#macro Ball(Kd)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb 0.1 / Kd diffuse 1 brilliance 1 specular 0 phong 0.6 phong_size 40 reflection 0 }
  }
#end
sphere { <-2.6, 0.6, 0.8>, 0.6 Ball(<0.8, 0.15, 0.1>) }
sphere { <2.6, 0.6, 0.8>, 0.6 Ball(<0.1, 0.25, 0.8>) }
