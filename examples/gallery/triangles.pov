// Hand-written POV-Ray 3.7 twin of triangles.xml (written from POV-Ray's documentation, not
// exported). A Lucent triangle is POV-Ray's triangle; with vertex normals na, nb, nc it is
// smooth_triangle { a, na, b, nb, c, nc }: both normalise the vertex normals, interpolate
// them barycentrically and normalise again. Both treat triangles as two-sided.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, k_a, k_s, n_s: pigment k_d, ambient k_a / k_d (POV-Ray scales ambient by the
// pigment), diffuse 1, Blinn specular k_s with roughness 1 / n_s.
#macro Plastic(Kd, Ka, Ks, Ns)
  texture {
    pigment { rgb Kd }
    finish { ambient rgb Ka / Kd diffuse 1 specular Ks roughness 1 / Ns phong 0 reflection 0 }
  }
#end

background { rgb <0.25, 0.3, 0.3> }
camera {
  perspective
  location <0, 3, 6>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 5> color rgb 1 }
// Directional light towards <1, -0.5, -0.5>: a parallel light far up the other way.
light_source { <-1, 0.5, 0.5> * 10000 color rgb 0.3 parallel point_at <0, 0, 0> }

plane { y, 0 Plastic(0.65, 0.1, 0, 1) }

// Flat: the four faces of a square pyramid, turned 45 degrees.
union {
  triangle { <-1, 0, 1>, <1, 0, 1>, <0, 1.8, 0> }
  triangle { <1, 0, 1>, <1, 0, -1>, <0, 1.8, 0> }
  triangle { <1, 0, -1>, <-1, 0, -1>, <0, 1.8, 0> }
  triangle { <-1, 0, -1>, <-1, 0, 1>, <0, 1.8, 0> }
  Plastic(<0.85, 0.45, 0.2>, <0.1, 0.05, 0.02>, 0.5, 40)
  rotate y * 45
  translate <-1.4, 0, 0>
}
// Smooth: the same faces with averaged vertex normals.
union {
  smooth_triangle { <-1, 0, 1>, <-0.9, 1, 0.9>, <1, 0, 1>, <0.9, 1, 0.9>, <0, 1.8, 0>, <0, 1, 0> }
  smooth_triangle { <1, 0, 1>, <0.9, 1, 0.9>, <1, 0, -1>, <0.9, 1, -0.9>, <0, 1.8, 0>, <0, 1, 0> }
  smooth_triangle { <1, 0, -1>, <0.9, 1, -0.9>, <-1, 0, -1>, <-0.9, 1, -0.9>, <0, 1.8, 0>, <0, 1, 0> }
  smooth_triangle { <-1, 0, -1>, <-0.9, 1, -0.9>, <-1, 0, 1>, <-0.9, 1, 0.9>, <0, 1.8, 0>, <0, 1, 0> }
  Plastic(<0.2, 0.5, 0.85>, <0.02, 0.05, 0.1>, 0.5, 40)
  rotate y * 45
  translate <1.4, 0, 0>
}
