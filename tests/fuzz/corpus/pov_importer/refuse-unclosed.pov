sphere { 0, 1 pigment { rgb 1 }
