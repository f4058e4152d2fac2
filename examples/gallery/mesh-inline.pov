// Hand-written POV-Ray 3.7 twin of mesh-inline.xml (written from POV-Ray's documentation, not
// exported). Lucent's inline mesh (positions, indices, optional normals: one per position)
// is POV-Ray's mesh2 with vertex_vectors, face_indices and normal_vectors (the normals are
// indexed like the vertices when normal_indices is absent). Interpolated normals are
// normalised again in both.
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

background { rgb <0.28, 0.25, 0.22> }
camera {
  perspective
  location <0, 3, 6.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.9, 0>
}
light_source { <-3, 6, 5> color rgb 1 }
// Directional light towards <1, -1, -1>: a parallel light far up the other way.
light_source { <-1, 1, 1> * 10000 color rgb 0.25 parallel point_at <0, 0, 0> }

plane { y, 0 Plastic(0.65, 0.1, 0, 1) }

// An octahedron, flat.
mesh2 {
  vertex_vectors { 6, <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  face_indices {
    8, <0, 2, 4>, <2, 1, 4>, <1, 3, 4>, <3, 0, 4>, <2, 0, 5>, <1, 2, 5>, <3, 1, 5>, <0, 3, 5>
  }
  Plastic(<0.8, 0.25, 0.4>, <0.1, 0.03, 0.05>, 0.6, 50)
  rotate y * 25
  scale <0.9, 1.1, 0.9>
  translate <-1.5, 1.1, 0>
}
// A ribbon bent around the y axis, with radial vertex normals.
mesh2 {
  vertex_vectors {
    6, <-0.866, 0, 0.5>, <0, 0, 1>, <0.866, 0, 0.5>, <-0.866, 1.6, 0.5>, <0, 1.6, 1>, <0.866, 1.6, 0.5>
  }
  normal_vectors {
    6, <-0.866, 0, 0.5>, <0, 0, 1>, <0.866, 0, 0.5>, <-0.866, 0, 0.5>, <0, 0, 1>, <0.866, 0, 0.5>
  }
  face_indices { 4, <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4> }
  Plastic(<0.25, 0.5, 0.85>, <0.03, 0.06, 0.1>, 0.6, 50)
  scale 1.1
  translate <1.4, 0.1, -0.5>
}
