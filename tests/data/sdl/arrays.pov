// Arrays: dimensions, initialisers, elements, copies.
#version 3.7;
#declare A = array[3] {1, 2, 3};
#declare B = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#debug concat(str(dimensions(B), 0, 0), " ", str(dimension_size(B, 1), 0, 0), " ")
#debug concat(str(dimension_size(B, 2), 0, 0), " ", str(dimension_size(B, 3), 0, 0), "\n")
#debug concat(str(B[1][2], 0, 0), " ", str(A[2] + B[0][1], 0, 0), "\n")
#declare C = array[4];
#declare C[2] = <1, 2, 3>;
#debug concat(str(defined(C[2]), 0, 0), str(defined(C[1]), 0, 0), "\n")
#declare S = array[2] {"ab", "cd"};
#debug concat(S[0], S[1], "\n")
#declare D = A;
#declare D[0] = 100;
#debug concat(str(A[0], 0, 0), " ", str(D[0], 0, 0), "\n")
#declare Sum = 0;
#for (I, 0, 2) #for (J, 0, 1) #declare Sum = Sum + B[J][I] * (I + 1); #end #end
#debug concat(str(Sum, 0, 0), "\n")
#declare E = array[2][2][2];
#declare E[1][0][1] = 7;
#debug concat(str(E[1][0][1], 0, 0), " ", str(A[1.5], 0, 0), "\n")
#undef C[2]
#debug concat(str(defined(C[2]), 0, 0), "\n")
#declare N = array[2] {array[2] {1, 2}, array[2] {3, 4}};
#declare Inner = N[1];
#debug concat(str(Inner[0], 0, 0), "\n")
