// Hand-written POV-Ray 3.7 twin of bump-map.xml (written from POV-Ray's documentation, not
// exported). Lucent's <bump-map src depth> on a mesh with uvs is POV-Ray's uv-mapped
// bump_map with bump_size depth: the image read at the mesh's uv_vectors, bilinearly
// (interpolate 2), without gamma (gamma 1.0: the stored grey levels), its grey level from
// the colour (use_color, the default).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

// Lucent's k_d, scalar k_a, k_p and phong size with a bump map of depth D: pigment k_d,
// ambient k_a / k_d (POV-Ray scales ambient by the pigment), diffuse 1.
#macro Bumpy(Kd, Ka, Kp, Np, D)
  texture {
    pigment { rgb Kd }
    normal {
      uv_mapping
      bump_map { png "textures/bumps.png" gamma 1.0 interpolate 2 use_color }
      bump_size D
    }
    finish { ambient rgb Ka / Kd diffuse 1 phong Kp phong_size Np specular 0 reflection 0 }
  }
#end

background { rgb <0.3, 0.3, 0.35> }
camera {
  perspective
  location <0, 3, 6.5>
  right -x * 320 / 240   // negative: our right-handed world, unchanged coordinates
  up y
  angle 50
  look_at <0, 0.8, 0>
}
light_source { <-3, 6, 5> color rgb 1 }
light_source { <4, 4, 4> color rgb 0.3 }

// A quad of two triangles with uvs at its corners, counter-clockwise seen from its front.
#macro Quad(A, B, C, D, UA, UB, UC, UD)
  vertex_vectors { 4, A, B, C, D }
  uv_vectors { 4, UA, UB, UC, UD }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
#end

// The floor, 8 by 8, the image 4 times each way: u along +x, v along +z.
mesh2 {
  Quad(<-4, 0, 4>, <4, 0, 4>, <4, 0, -4>, <-4, 0, -4>, <0, 4>, <4, 4>, <4, 0>, <0, 0>)
  Bumpy(<0.7, 0.65, 0.55>, 0.2, 0, 40, 1.5)
}
// The wall at z = -2.5: u along -x, v up.
mesh2 {
  Quad(<-4, 0, -2.5>, <4, 0, -2.5>, <4, 4, -2.5>, <-4, 4, -2.5>, <4, 0>, <0, 0>, <0, 2>, <4, 2>)
  Bumpy(<0.55, 0.6, 0.7>, 0.2, 0.3, 40, 1.5)
}
// The tilted panel, sunk bumps: u along its -x, v up its slope.
mesh2 {
  Quad(<-0.9, 0, 0>, <0.9, 0, 0>, <0.9, 1.6, -0.8>, <-0.9, 1.6, -0.8>, <1, 0>, <0, 0>, <0, 1>, <1, 1>)
  Bumpy(<0.8, 0.5, 0.3>, 0.15, 0.4, 30, -1.5)
  rotate y * 25
  translate <1.7, 0.01, 0.6>
}
// The smooth sphere: k_d 0.9, k_a 0.15, Blinn specular 0.4 with n_s 50 (roughness 1/50).
sphere {
  <-1.2, 0.8, 0.3>, 0.8
  texture {
    pigment { rgb 0.9 }
    finish { ambient rgb 0.15 / 0.9 diffuse 1 specular 0.4 roughness 1 / 50 phong 0 reflection 0 }
  }
}
