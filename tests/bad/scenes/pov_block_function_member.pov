#version 3.7;
#include "functions.inc"
isosurface { function { y - f_checker(x, y, z).red } contained_by { box { -1, 1 } } }
