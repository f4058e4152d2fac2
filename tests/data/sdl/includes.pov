// POV-Ray's standard includes, read as the SDL they are, and their macros used.
#version 3.7;
#include "colors.inc"
#include "math.inc"
#include "strings.inc"
#include "rand.inc"
#include "arrays.inc"
#include "transforms.inc"
#debug concat(CRGBStr(Orange, 0, 3), "\n")
#debug concat(vstr(5, MediumSeaGreen, ",", 0, 4), "\n")
#debug concat(VStr(VPerp_To_Vector(<1, 2, 3>)), "\n")
#debug concat(str(VAngleD(x, y + x), 0, 6), " ", str(VDist(<1, 2, 3>, <4, 6, 3>), 0, 3), "\n")
#debug concat(str(Interpolate(0.5, 0, 1, 10, 20, 2), 0, 6), "\n")
#debug concat(str(Interpolate(0.25, 0, 1, 10, 20, 0), 0, 6), "\n")
#declare Arr = array[5] {5, 3, 9, 1, 7};
Sort_Array(Arr)
#debug concat(str(Arr[0], 0, 0), str(Arr[1], 0, 0), str(Arr[2], 0, 0), str(Arr[3], 0, 0))
#debug concat(str(Arr[4], 0, 0), "\n")
#debug concat(str(Mean(Arr), 0, 4), " ", str(Std_Dev(Arr, Mean(Arr)), 0, 6), "\n")
#declare R = seed(7);
#debug concat(str(Rand_Normal(0, 1, R), 0, 8), " ", str(RRand(1, 2, R), 0, 8), "\n")
#debug concat(vstr(3, VRand(RdmA), ",", 0, 8), "\n")
#debug concat(Str(12.5), " ", Vstr(<1, 2, 3>, 0, 1), "\n")
#debug concat(vstr(3, VProject_Axis(<1, 2, 3>, y), ",", 0, 3), "\n")
