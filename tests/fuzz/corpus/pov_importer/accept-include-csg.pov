#include "colors.inc"
box { -1, 1 pigment { Red } rotate 45*y }
difference { sphere { 0, 1 } cylinder { -2*x, 2*x, 0.5 } }
