// Hand-written POV-Ray 3.7 twin of ovus.xml (written from POV-Ray's documentation, not
// exported), in POV-Ray's own left-handed numbers: every z of the XML negated, rotations
// about x and y turned the other way (the importer's mapping). Lucent's material (k_a, k_d,
// specular k_s with shininess s) is pigment k_d, ambient k_a / k_d, diffuse 1, specular k_s
// with roughness 1/s; mapping="uv" is POV-Ray's uv_mapping.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }
background { rgb <0.12, 0.14, 0.18> }

camera {
  perspective
  location <0, 3.4, -9.5>
  right x * 320 / 240
  up y
  angle 48
  look_at <0, 0.8, 0>
}
light_source { <-5, 8, -7> color rgb 1 }
light_source { <4, 3, -6> color rgb 0.4 }

#macro Surface(Kd, Ka, Ks, Shininess)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Shininess phong 0 reflection 0 }
  }
#end

plane {
  y, 0
  texture {
    pigment { rgb <0.6, 0.6, 0.55> }
    finish { ambient rgb <0.05, 0.05, 0.05> / <0.6, 0.6, 0.55> diffuse 1 specular 0 phong 0 }
  }
}

// POV-Ray's template egg, standing on the floor.
ovus {
  1, 0.65
  Surface(<0.9, 0.8, 0.7>, <0.09, 0.08, 0.07>, 0.4, 40)
  translate <-2.6, 1, -0.3>
}

// Wider at the top, on its side; uv_mapping reads the ovus's (u, v).
ovus {
  0.6, 1
  pigment { uv_mapping checker rgb <0.9, 0.75, 0.2>, rgb <0.15, 0.3, 0.65>
            scale <0.125, 0.25, 1> translate z * 0.5 }
  finish { ambient 0.2 diffuse 0.8 specular 0 phong 0 reflection 0 }
  rotate z * 70
  rotate y * -30
  translate <0.1, 1.2, 0.4>
}

// An egg shell cut open by a tilted slab.
difference {
  ovus { 1, 0.65 }
  ovus { 1, 0.65 scale 0.85 }
  box { <-2, 0, -2>, <2, 2, 2> rotate x * -30 translate <0, 0.75, 0> }
  Surface(<0.6, 0.8, 0.9>, <0.06, 0.08, 0.1>, 0.5, 60)
  rotate y * 25
  translate <2.6, 1, -0.4>
}
