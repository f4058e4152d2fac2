#version 3.7;
#declare S = function { spline { linear_spline #for (I, 0, 40000) I, <sin(I), 0> #end } }
isosurface { function { y - S(x).x } contained_by { box { -1, 1 } } }
