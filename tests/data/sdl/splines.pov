// Splines: every kind, evaluated before, at, between and after the entries, the kind
// changed by a call, copied and extended, entries given out of order and twice, float
// entries, 2- to 5-component vectors, and spline functions. Every number to 15 decimals,
// so that Lucent must give POV-Ray's values.
#version 3.7;
#macro Show(Label, V) #debug concat(Label, " ", vstr(5, V, ",", 0, 15), "\n") #end
#macro Show2(Label, V) #debug concat(Label, " ", vstr(2, V, ",", 0, 15), "\n") #end
#macro Show3(Label, V) #debug concat(Label, " ", vstr(3, V, ",", 0, 15), "\n") #end
#declare P = spline {
  -2, <-5, 3, 0>, -1, <-2, 2, 0>, 0, <0, 2, 0>, 1, <2, 2, 1>, 2.5, <5, 3, 0>,
  3, <5, 4, 4> 4, <0, 5, 5>, 5.2, <-2, 4, 9>, 6, <2, 3, 9>
}
#declare Q = spline { P cubic_spline }
#declare R = spline { P natural_spline }
#declare S = spline { P quadratic_spline }
#declare I = 0;
#while (I < 22)
  #declare T = -3 + I*0.47;
  Show3(concat("linear ", str(T, 0, 2)), P(T))
  Show3(concat("cubic ", str(T, 0, 2)), Q(T))
  Show3(concat("natural ", str(T, 0, 2)), R(T))
  Show3(concat("quadratic ", str(T, 0, 2)), S(T))
  Show3(concat("P as cubic ", str(T, 0, 2)), P(T, cubic_spline))
  Show3(concat("Q as quadratic ", str(T, 0, 2)), Q(T, quadratic_spline))
  #declare I = I + 1;
#end
// Out of order, a parameter given twice (the later one replaces it) and the last parameter
// given twice (POV-Ray keeps the first); floats become 2-component vectors.
#declare U = spline { linear_spline 3, 7 1, 2 2, <4, 5> 1, 3 3, 9 }
Show2("U 1", U(1))
Show2("U 1.5", U(1.5))
Show2("U 3", U(3))
// The most components any entry has: colours and 4-vectors.
#declare V = spline { natural_spline 0, <1, 2, 3, 4, 5> 1, <0, 1, 0> 2, <2, 2, 2, 2> 3.5, 1 }
Show("V 0.7", V(0.7))
Show("V 2.9", V(2.9))
#declare C = V(1.3) + <1, 1, 1, 1, 1>;
Show("C", C)
#debug concat("V(2).y*2 ", str(V(2.2).y*2, 0, 15), "\n")
// Two entries: cubic averages them; one entry: always it.
#declare W = spline { cubic_spline 0, <0, 0, 0> 1, <2, 4, 6> }
Show3("W", W(0.3))
#declare X1 = spline { 5, <1, 2, 3> }
Show3("X1", X1(-10))
// Spline functions, called in expressions and in functions.
#declare F = function { spline { cubic_spline -0.001, <0, 0, 0> 0.25, <0.25, 0.5, 0> 0.5, <0.5, 0.1, 0> 0.75, <0.75, 0.9, 0> 1.001, <1, 0, 0> } }
Show3("F 0.4", F(0.4))
#declare G = function { F(x).y + F(y).x*2 + F(z).gray }
#debug concat("G ", str(G(0.3, 0.6, 0.8), 0, 15), "\n")
// Passed to a macro by reference and called inside it.
#macro At(Spl, T) Spl(T) #end
Show3("At", At(Q, 2.2))
