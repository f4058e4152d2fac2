#version 3.7;
#declare S = function { spline { cubic_spline 0, <0, 0, 0> 1, <1, 2, 3> 2, <2, 2, 2> 3, <3, 0, 1> } }
isosurface { function { y - S(x) } contained_by { box { -1, 1 } } }
