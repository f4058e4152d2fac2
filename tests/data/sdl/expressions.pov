// Expressions: precedence, promotions, comparisons, conditionals, components, colours.
#version 3.7;
#macro P(L, V) #debug concat(L, " ", str(V, 0, 10), "\n") #end
#macro PV(L, V) #debug concat(L, " ", vstr(3, V, ",", 0, 8), "\n") #end
#macro P5(L, V) #debug concat(L, " ", vstr(5, V, ",", 0, 6), "\n") #end
P("prec", 1 + 2 * 3 - 4 / 8)
P("neg", -2 * -3)
P("paren", (1 + 2) * 3)
P("rel", (1 < 2) + (2 <= 2) + (3 = 3) + (3 != 3) + (4 >= 5) + (5 > 4))
P("eps", (1 = 1 + 1e-11))
P("and", (1 & 0) + 10 * (1 | 0) + 100 * (!0))
P("chain", (1 | 0 & 0))
P("cond", (2 > 1 ? 10 : 20))
P("cond2", (0 ? 10 : 20) + 1)
P("unary", - - 3)
P("plus", + + 4)
P("numbers", 1. + .5 + 1e-3 + 2.5E2)
PV("vec", <1, 2, 3> * 2 + 1)
PV("promote", 3 * x + <0, 1, 0>)
PV("div", <2, 4, 8> / <2, 2, 2>)
PV("commas", <1 2 3>)
#declare V = <1.5, -2, 3>;
P("dotx", V.x + V.y * 10 + V.z * 100)
PV("xyz", x + 2 * y + 3 * z)
PV("uvt", u + v + t)
#declare C = rgb <0.2, 0.4, 0.6>;
P5("rgb", C)
P5("rgbf", rgbf <0.1, 0.2, 0.3, 0.4>)
P5("rgbt", rgbt <0.1, 0.2, 0.3, 0.4>)
P5("rgbft", rgbft <0.1, 0.2, 0.3, 0.4, 0.5>)
#declare D = color red 0.5 green 0.25 filter 0.75;
P5("keys", D)
#declare E = color 0.5;
P5("color f", E)
#declare F = rgb 1;
P5("rgb 1", F)
P("comp", C.red + C.green * 10 + C.blue * 100)
P("gray", C.gray)
#declare G = rgb <1, 0.5, 0> * 0.5;
P5("scaled", G)
P5("five", <1, 2, 3, 4, 5>)
#declare H = rgb <1, 0.5, 0> transmit 0.25;
P5("transmit", H)
#declare U = <1, 2>;
P("uv", U.u + U.v * 10)
#declare W = <1, 2, 3, 4>;
P("4d", W.t)
P("div0", 1 / 0)
PV("cmpvec", (<1, 2, 3> = <1, 0, 3>))
