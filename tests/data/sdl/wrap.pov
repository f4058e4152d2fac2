// #debug text as POV-Ray prints it: cut into lines of 160 then 80 characters, at a space
// among the last quarter when there is one, across several #debug directives.
#version 3.7;
#declare I = 0;
#while (I < 30)
  #debug concat(str(I * 1.5, 0, 3), " ")
  #declare I = I + 1;
#end
#debug "\n"
#declare S = "";
#for (J, 1, 10) #declare S = concat(S, "abcdefghijklm"); #end
#debug concat(S, "\n")
#debug concat("short\n", S, " tail\n")
#debug concat("123456789 123456789 123456789 123456789 123456789 123456789 123456789 1234")
#debug concat("56789 123456789 123456789\n")
#declare T = "";
#for (J, 1, 15) #declare T = concat(T, "0123456789 "); #end
#debug T
#debug "unfinished at the end"
