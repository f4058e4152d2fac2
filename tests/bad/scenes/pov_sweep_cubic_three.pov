#version 3.7;
sphere_sweep { cubic_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 }
