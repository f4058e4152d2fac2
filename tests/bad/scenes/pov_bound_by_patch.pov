sphere {
  0, 1 pigment { rgb 1 }
  bounded_by { mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } } }
}
