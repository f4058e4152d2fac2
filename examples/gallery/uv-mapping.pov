// Hand-written POV-Ray 3.7 twin of uv-mapping.xml (written from POV-Ray's documentation, not
// exported). Lucent's mapping="uv" is POV-Ray's uv_mapping: the rest of the pigment block is
// evaluated at (u, v, 0) of the mesh's uv_vectors, placed by the transforms written in it.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 adc_bailout 0.0039 }

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

// Lucent's scalar ambient and a texture without diffuse: diffuse 1, the ambient scaled by
// the pigment (as POV-Ray's is).
#macro Plain(Ka) finish { ambient Ka diffuse 1 specular 0 reflection 0 } #end

// A quad of two triangles with uvs at its corners.
#macro Quad(A, B, C, D, UA, UB, UC, UD)
  vertex_vectors { 4, A, B, C, D }
  uv_vectors { 4, UA, UB, UC, UD }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
#end

// The floor: an eight-armed spiral2 about uv (1, 1).
mesh2 {
  Quad(<-4, 0, 4>, <4, 0, 4>, <4, 0, -4>, <-4, 0, -4>, <0, 0>, <2, 0>, <2, 2>, <0, 2>)
  texture {
    pigment {
      uv_mapping spiral2 8
      color_map { [0.5 rgb <0.6, 0.15, 0.1>] [0.5 rgb <0.9, 0.85, 0.7>] }
      scale 0.8 translate <1, 1, 0>
    }
    Plain(0.2)
  }
}
// The wall: bricks in (u, v) space, off the plane z = 0 of pattern space.
mesh2 {
  Quad(<-4, 0, -2.5>, <4, 0, -2.5>, <4, 4, -2.5>, <-4, 4, -2.5>, <0, 0>, <8, 0>, <8, 4>, <0, 4>)
  texture {
    pigment {
      uv_mapping brick rgb <0.8, 0.8, 0.75>, rgb <0.55, 0.2, 0.1>
      brick_size <1, 0.5, 1> mortar 0.08
      translate <0, 0, 0.5>
    }
    Plain(0.2)
  }
}
// The tilted panel: a checker squeezed by its uvs.
mesh2 {
  Quad(<-0.9, 0, 0>, <0.9, 0, 0>, <0.9, 1.6, -0.8>, <-0.9, 1.6, -0.8>, <0, 0>, <4, 0>, <3, 4>, <1, 4>)
  texture {
    pigment { uv_mapping checker rgb <0.9, 0.8, 0.2>, rgb <0.15, 0.25, 0.6> translate <0, 0, 0.5> }
    finish { ambient 0.15 diffuse 1 phong 0.4 phong_size 30 specular 0 reflection 0 }
  }
  rotate y * 25
  translate <1.7, 0.01, 0.6>
}
// The fan: a gradient along u + v.
mesh2 {
  vertex_vectors { 5, <-2.2, 0.2, 0.4>, <-0.6, 0.2, 0.4>, <-0.6, 1.8, 0.4>, <-2.2, 1.8, 0.4>, <-1.4, 1, 0.9> }
  uv_vectors { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 0.5> }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  texture {
    pigment {
      uv_mapping gradient <1, 1, 0>
      color_map { [0 rgb <0.1, 0.5, 0.2>] [1 rgb <0.95, 0.95, 0.5>] }
      scale 0.25
    }
    Plain(0.15)
  }
}
