sphere { 0, 1 pigment { rgb 1 } }
rainbow { direction <0, 0, 1> angle 42 width 5 arc_angle 90 falloff_angle 120
          color_map { [0 rgb 1] } }
