camera { location -5*z look_at 0 }
sphere { 0, 1 pigment { pigment_pattern { checker pigment { image_map { png "pattern_images/grey_trns.png" } } pigment { rgb 1 } } } }
