#version 3.7;
sphere { 0, 1 pigment { image_map { png "pattern_images/grey_trns.png" gamma -2 } } }
