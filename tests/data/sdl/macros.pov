// Macros: values, references, recursion, locals and POV-Ray's scoping.
#version 3.7;
#macro Sq(X) (X * X) #end
#debug concat(str(Sq(3), 0, 0), " ", str(Sq(1 + 1), 0, 0), "\n")
#macro Inc(A) #declare A = A + 1; #end
#declare B = 5;
Inc(B) Inc(B)
#debug concat("B ", str(B, 0, 0), "\n")
#macro IncLocal(A) #local A = A + 1; #end
#declare C = 5;
IncLocal(C)
#debug concat("C ", str(C, 0, 0), "\n")
#declare D = 5;
Inc(D + 0)
#debug concat("D ", str(D, 0, 0), "\n")
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#debug concat("fact ", str(Fact(10), 0, 0), "\n")
#macro Fib(N) #if (N < 2) N #else (Fib(N - 1) + Fib(N - 2)) #end #end
#debug concat("fib ", str(Fib(15), 0, 0), "\n")
#declare G = 1;
#macro Scope()
  #local G = 2;
  #declare H = G * 10;
  #local L = 3;
#end
Scope()
#debug concat("G ", str(G, 0, 0), " H ", str(H, 0, 0), " L ", str(defined(L), 0, 0), "\n")
#macro SetGlobal() #declare G = 7; #end
#macro Shadow() #local G = 5; SetGlobal() #debug concat("inner ", str(G, 0, 0), "\n") #end
Shadow()
#debug concat("outer ", str(G, 0, 0), "\n")
#macro Str2(A, B) concat(A, "-", B) #end
#debug concat(Str2("x", Str2("y", "z")), "\n")
#macro Vec(A) <A, A * 2, A * 3> #end
#declare V = Vec(2) + Vec(1);
#debug concat(vstr(3, V, ",", 0, 0), "\n")
#macro Expr() 1 + 2 #end
#debug concat(str(Expr() * 3, 0, 0), "\n")
#declare Q = 1 + Expr();
#debug concat(str(Q, 0, 0), "\n")
#macro Arr(A) #declare A[1] = 9; #end
#declare Ar = array[2] {1, 2};
Arr(Ar)
#debug concat(str(Ar[1], 0, 0), "\n")
#macro Elem(E) #declare E = E * 10; #end
Elem(Ar[0])
#debug concat(str(Ar[0], 0, 0), "\n")
#macro Twice(S) concat(S, S) #end
#declare W = Twice("ab");
#debug concat(W, "\n")
#macro Early(N)
  #if (N > 2) #debug "big" #break #end
  #debug "small"
#end
Early(1) Early(5)
#debug "\n"
#macro Redefined() 1 #end
#macro Redefined() 2 #end
#debug concat(str(Redefined(), 0, 0), "\n")
