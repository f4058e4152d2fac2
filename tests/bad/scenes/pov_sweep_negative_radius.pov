#version 3.7;
sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, -1 }
