// Lights projected through objects (projected_through), against POV-Ray 3.7: a ring and a
// ball moved with their light and with transforms written after projected_through; a ball
// between them and the light that casts no shadow, and one nearer the floor that does; a
// shadowless light projected through a turned box (its texture dropped, as POV-Ray drops it);
// an area light projected through a disc with a hole.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 9, -9> look_at <0, 0, 0.5> angle 60 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0.02 diffuse 0.8 } }

#declare Ring = union {
  torus { 1, 0.15 }
  sphere { 0, 0.35 }
}

light_source {
  <0, 8, 0> rgb <1, 0.85, 0.6>
  projected_through { Ring scale 0.5 translate y * 4 }
  translate <-2.5, 0, 0>
}
// Between the ring and the light: no shadow.
sphere { <-2.5, 6, 0>, 0.3 pigment { rgb <1, 0.3, 0.3> } }
// Between the floor and the ring: a shadow inside the ring of light.
sphere { <-1.5, 1, 0>, 0.3 pigment { rgb <0.3, 1, 0.3> } }

light_source {
  <2.5, 8, 1> rgb <0.5, 0.6, 1> shadowless
  projected_through {
    box { -0.5, 0.5 pigment { rgb <1, 0, 0> } }
    rotate y * 30 translate <2.5, 5, 1>
  }
}

light_source {
  <0, 8, 4> rgb 0.6
  area_light x * 0.6, z * 0.6, 4, 4
  projected_through { difference { cylinder { <0, -0.01, 0>, <0, 0.01, 0>, 0.8 } cylinder { <0, -1, 0>, <0, 1, 0>, 0.3 } } translate <0, 4, 4> }
}
sphere { <0.5, 0.4, 4>, 0.4 pigment { rgb 0.8 } }
