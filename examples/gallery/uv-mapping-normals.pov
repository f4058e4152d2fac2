// Hand-written POV-Ray 3.7 twin of uv-mapping-normals.xml (written from POV-Ray's
// documentation, not exported). Lucent's <normal mapping="uv"> bending the object's normal is
// POV-Ray's texture { uv_mapping ... normal {...} } (its normal bent in the space of the
// transforms written after the texture, the object's); bend-space="world" is POV-Ray's
// normal { uv_mapping ... } (the world normal bent). A <pigment-map> entry with mapping="uv"
// is POV-Ray's uv_mapping entry. Lucent's world is written unchanged (right -x).
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

#macro Quad(A, B, C, D, UA, UB, UC, UD)
  vertex_vectors { 4, A, B, C, D }
  uv_vectors { 4, UA, UB, UC, UD }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
#end

// The floor: bumps at (u, v, 0).
mesh2 {
  Quad(<-4, 0, 4>, <4, 0, 4>, <4, 0, -4>, <-4, 0, -4>, <0, 0>, <4, 0>, <4, 4>, <0, 4>)
  texture {
    uv_mapping
    pigment { rgb <0.6, 0.6, 0.65> }
    normal { bumps 0.6 scale 0.08 }
    finish { ambient rgb 0.2 / <0.6, 0.6, 0.65> diffuse 1 phong 0.3 phong_size 20 specular 0 reflection 0 }
  }
}
// Left: ridges along u bending the panel's own normal.
mesh2 {
  Quad(<-0.8, 0, 0>, <0.8, 0, 0>, <0.8, 1.6, 0>, <-0.8, 1.6, 0>, <0, 0>, <1, 0>, <1, 1>, <0, 1>)
  texture {
    uv_mapping
    pigment { rgb <0.85, 0.6, 0.3> }
    normal { gradient x 1.2 scale 0.2 }
    finish { ambient rgb 0.15 / <0.85, 0.6, 0.3> diffuse 1 phong 0.5 phong_size 30 specular 0 reflection 0 }
  }
  rotate y*35 translate <-1.9, 0.01, -0.3>
}
// Right: the same ridges bending the world normal.
mesh2 {
  Quad(<-0.8, 0, 0>, <0.8, 0, 0>, <0.8, 1.6, 0>, <-0.8, 1.6, 0>, <0, 0>, <1, 0>, <1, 1>, <0, 1>)
  texture {
    pigment { rgb <0.3, 0.6, 0.85> }
    normal { uv_mapping gradient x 1.2 scale 0.2 }
    finish { ambient rgb 0.15 / <0.3, 0.6, 0.85> diffuse 1 phong 0.5 phong_size 30 specular 0 reflection 0 }
  }
  rotate y*-35 translate <1.9, 0.01, -0.3>
}
// The middle panel: a uv-mapped checker as a map's entry.
mesh2 {
  Quad(<-0.8, 0, 0>, <0.8, 0, 0>, <0.8, 1.6, 0>, <-0.8, 1.6, 0>, <0, 0>, <1, 0>, <1, 1>, <0, 1>)
  texture {
    pigment { gradient x
      pigment_map {
        [0.35 uv_mapping checker rgb <0.9, 0.8, 0.2>, rgb <0.15, 0.25, 0.6> scale 0.125 translate <0, 0, 0.5>]
        [0.65 rgb <0.8, 0.3, 0.25>]
      }
      scale 1.6 translate <-0.8, 0, 0> }
    finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 specular 0 reflection 0 }
  }
  rotate x*-10 translate <0, 0.01, 0.6>
}
