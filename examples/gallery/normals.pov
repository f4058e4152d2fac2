// Hand-written POV-Ray 3.7 twin of normals.xml (written from POV-Ray 3.7's documentation, not
// exported). Lucent's <normal type="T" depth="d"> is POV-Ray's normal { T d } with the same
// frequency and transform; the pattern is written inside the normal and the sphere's
// translation after the texture, so that the pattern moves with the sphere. Lucent's ambient
// k_a of a plain colour is not multiplied by the diffuse colour, so it is ambient k_a/k_d
// here; specular k_s with shininess n_s is specular k_s with roughness 1/n_s.
// Known difference: where a bump would tilt the normal away from the viewer, Lucent keeps the
// unperturbed normal and POV-Ray the tilted one, so a few silhouette pixels differ.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

background { rgb <0.3, 0.4, 0.6> }
camera {
  perspective
  location <0, 5.5, 9>
  right -x * 400 / 200   // negative: Lucent's right-handed world with unchanged coordinates
  up y
  angle 50
  look_at <0, 0.4, 0.4>
}
light_source { <-5, 8, 7> color rgb 1 }
light_source { <6, 4, 6> color rgb 0.3 }

plane {
  y, 0
  texture {
    pigment { checker rgb <0.85, 0.85, 0.8>, rgb <0.45, 0.45, 0.45> }
    finish { ambient 0.1 diffuse 0.8 brilliance 1 specular 0 phong 0 reflection 0 }
  }
}

// Each sphere starts from Lucent's defaults (no highlight, brilliance 1, no reflection).
#declare Base = finish { diffuse 1 brilliance 1 specular 0 phong 0 reflection 0 }

// Back row.
sphere {
  0, 0.8
  texture {
    pigment { rgb <0.2, 0.4, 0.8> }
    normal { ripples 0.5 frequency 10 }
    finish { Base ambient rgb 0.1 / <0.2, 0.4, 0.8> phong 0.8 phong_size 60 }
  }
  translate <-2.3, 0.8, -0.8>
}
sphere {
  0, 0.8
  texture {
    pigment { rgb <0.2, 0.7, 0.6> }
    normal { waves 0.6 frequency 6 }
    finish { Base ambient rgb 0.1 / <0.2, 0.7, 0.6> phong 0.8 phong_size 60 }
  }
  translate <0, 0.8, -0.8>
}
sphere {
  0, 0.8
  texture {
    pigment { rgb <0.8, 0.75, 0.7> }
    normal { bumps 0.5 scale 0.15 }
    finish { Base ambient rgb 0.1 / <0.8, 0.75, 0.7> specular 0.8 roughness 1 / 80 }
  }
  translate <2.3, 0.8, -0.8>
}

// Front row: metallic dents (the highlight takes the pigment's colour) and wrinkles.
sphere {
  0, 0.8
  texture {
    pigment { rgb <0.85, 0.6, 0.2> }
    normal { dents 1 scale 0.25 }
    finish { Base ambient rgb 0.1 / <0.85, 0.6, 0.2> specular 0.8 roughness 1 / 80 metallic }
  }
  translate <-1.2, 0.8, 1.6>
}
sphere {
  0, 0.8
  texture {
    pigment { rgb <0.8, 0.2, 0.2> }
    normal { wrinkles 0.6 scale 0.3 }
    finish { Base ambient rgb 0.1 / <0.8, 0.2, 0.2> phong 0.8 phong_size 60 }
  }
  translate <1.2, 0.8, 1.6>
}
