#version 3.7;
sphere_sweep { linear_spline 1, <0, 0, 0>, 1 }
