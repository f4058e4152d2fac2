sphere { 0, 1 pigment { rgb 1 } }
rainbow { angle 42 width 5 color_map { [0 rgb 1] } }
