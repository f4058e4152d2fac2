sphere {
  0, 1 pigment { rgb 1 }
  clipped_by { union { box { -1, 1 } triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } } }
}
