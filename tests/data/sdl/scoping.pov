// Include files: their #local identifiers end with them; #declare reaches the scene.
#version 3.7;
#declare A = 1;
#include "scoping.inc"
#debug concat(str(A, 0, 0), " ", str(defined(IncLocal), 0, 0), " ", str(IncGlobal, 0, 0), "\n")
#include "scoping"
#debug concat(str(A, 0, 0), "\n")
