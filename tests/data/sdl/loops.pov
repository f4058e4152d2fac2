// Conditions and loops: #if/#elseif/#else, #while, #for, #switch, #break, #ifdef, #undef.
#version 3.7;
#declare I = 0;
#while (I < 5)
  #if (mod(I, 2) = 0)
    #debug concat("even ", str(I, 0, 0), "\n")
  #elseif (I = 3)
    #debug "three\n"
  #else
    #debug concat("odd ", str(I, 0, 0), "\n")
  #end
  #declare I = I + 1;
#end
#for (J, 1, 2, 0.25) #debug concat(str(J, 0, 2), " ") #end
#debug "\n"
#for (J, 3, 1, -1) #debug str(J, 0, 0) #end
#debug "\n"
#for (K, 5, 1) #debug "never" #end
#debug concat("K ", str(K, 0, 0), "\n")
#for (J, 0, 10)
  #if (J = 3) #break #end
  #debug str(J, 0, 0)
#end
#debug "\n"
#macro Sw(N)
  #switch (N)
    #case (1) #debug "one " #break
    #case (2) #debug "two "
    #case (3) #debug "two-or-three " #break
    #range (4, 6) #debug "four-to-six " #break
    #else #debug "other "
  #end
#end
Sw(1) Sw(2) Sw(3) Sw(5) Sw(9)
#debug "\n"
#ifdef (I) #debug "I defined\n" #end
#ifndef (Nope) #debug "Nope undefined\n" #end
#undef I
#ifdef (I) #debug "still\n" #else #debug "gone\n" #end
#if (0) #if (1) #debug "x" #end #else #debug "nested skip ok\n" #end
#declare N = 0;
#while (N < 10) #declare N = N + 1; #if (N = 2) #break #end #end
#debug concat("N ", str(N, 0, 0), "\n")
#declare M = 0;
#while (M < 3)
  #declare M = M + 1;
  #switch (M)
    #case (2) #debug "two" #break
    #else #debug "not-two"
  #end
  #debug ";"
#end
#debug "\n"
/* a /* nested */ block comment */ #debug "after comment\n"
