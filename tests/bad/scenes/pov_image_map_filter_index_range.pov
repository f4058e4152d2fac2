#version 3.7;
sphere { 0, 1 pigment { image_map { png "pattern_images/mm_palette.png" filter 16, 0.5 } } }
