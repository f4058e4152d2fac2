#macro Ring(N) union { #local I = 0; #while (I < N) sphere { <cos(I), sin(I), 0>, 0.1 } #local I = I + 1; #end } #end
object { Ring(12) pigment { rgb 1 } }
