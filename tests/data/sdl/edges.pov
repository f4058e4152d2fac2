// Corner cases: conversions at the edges of int, float steps, references passed on,
// colour keys, strings holding comment marks, redeclared types.
#version 3.7;
#macro P(L, V) #debug concat(L, " ", str(V, 0, 10), "\n") #end
P("int big", int(1e10))
P("div neg", div(-7.5, 2))
P("mod frac", mod(-7.25, 2))
P("max1", max(3))
P("band1", bitwise_and(6))
P("inf", 1e300 * 1e300)
#declare N = 0;
#for (I, 0, 1, 0.1) #declare N = N + 1; #end
P("float steps", N)
P("after for", I)
#macro Inner(R) #declare R = R * 2; #end
#macro Outer(R) Inner(R) Inner(R) #end
#declare Q = 3;
Outer(Q)
P("ref of ref", Q)
#macro Count(D) #local L = D; #if (D > 0) #local L = L + Count(D - 1); #end L #end
P("locals per call", Count(4))
#declare F = 3;
#macro M(F) F * 2 #end
P("shadow", M(F + 1))
#declare C = color rgb <1, 0, 0> filter 0.5 transmit 0.2;
#debug concat(vstr(5, C, ",", 0, 3), "\n")
#declare C2 = <1, 2, 3, 4, 5>;
P("filter", C2.filter)
#declare Mix = rgb <1, 0, 0> + <0, 0, 1>;
#debug concat(vstr(5, Mix, ",", 0, 1), "\n")
#declare Mul = C2 * <1, 0, 1>;
#debug concat(vstr(5, Mul, ",", 0, 1), "\n")
#debug concat("a // b", " /* c */", "\n")
#declare S = "x";
#declare S = 1;
P("retyped", S)
#undef S
#ifndef (S) #debug "undef ok\n" #end
#debug concat(str(strlen(""), 0, 0), substr("abc", 1, 3), str(asc(""), 0, 0), "\n")
P("val", val("  -3.5e2"))
P("val empty", val(""))
#if (version >= 3.7) #debug "v37\n" #end
#macro Name(X) concat("<", X, ">") #end
#if (Name("a") = "<a>") #debug "string macro compare\n" #end
#declare A = array[3];
#declare A[1] = 5;
#ifdef (A[1]) #debug "elem defined\n" #end
#ifdef (A[2]) #debug "wrong\n" #else #debug "elem undefined\n" #end
P("defined macro", defined(Name))
#debug concat(vstr(2, <1.5, 2.5>, ";", 0, 1), "\n")
#debug concat("\u0041\u0062", "\n")
P("select nest", select(-1, select(1, 2, 3), 4))
P("vrot90", vrotate(x, <0, 0, 90>).x)
P("vaxis0", vaxis_rotate(<1, 2, 3>, y, 0).z)
#switch (0.75)
  #range (0.5, 1.5) #debug "in range\n" #break
  #else #debug "out\n"
#end
#declare K = 0;
#while (K < 3)
  #declare K = K + 1;
  #for (J, 1, K) #debug str(J, 0, 0) #end
#end
#debug "\n"
P("neg zero", -0)
P("precedence", 2 - 3 - 4)
P("div chain", 64 / 4 / 2)
P("exp form", 1.5e+2 + 2E-1)
